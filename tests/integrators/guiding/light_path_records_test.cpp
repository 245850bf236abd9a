// Light paths teach the guide the directions light arrives from: a floor
// lit only by a reflector above it learns to look up at the reflector.

#include "integrators/path/guiding/light_path_records.h"

#include <gtest/gtest.h>

#include "core/render/path_settings.h"
#include "core/sampling/sampler.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// A 2 m floor (normal +y), a 0.6 m reflector 1 m above it facing down, and
// between them a 0.2 m light facing up: one-sided, it lights the reflector
// alone, and the floor sees its light only by way of the reflector (or of
// the light's back, which the reflector lights).
const char* kReflectorScene = R"(<scene version="3.0.0">
  <shape type="rectangle">
    <transform name="to_world"><rotate x="1" angle="-90"/></transform>
  </shape>
  <shape type="rectangle">
    <transform name="to_world"><scale value="0.3"/><rotate x="1" angle="90"/><translate y="1"/></transform>
  </shape>
  <shape type="rectangle">
    <transform name="to_world"><scale value="0.1"/><rotate x="1" angle="-90"/><translate y="0.7"/></transform>
    <emitter type="area"><rgb name="radiance" value="50"/></emitter>
  </shape>
</scene>)";

// The share of directions drawn from the floor's learned distribution
// that point within 60 degrees of straight up: a quarter of the sphere, so
// a quarter if nothing were learnt, and three quarters for cosine-weighted
// directions. From every point of the floor every point of the reflector
// lies there (at most 1.72 m aside, 1 m up), so nearly all the light the
// floor receives comes from there (the light's small back, which the
// reflector lights, sends a little from lower down).
double share_looking_up(const GuidingTree& tree, Vec3 at) {
  GuidingTree& t = const_cast<GuidingTree&>(tree);
  const DirectionalDistribution& d = t.region_at(at).guides[normal_bucket({0, 1, 0})].sampling;
  EXPECT_FALSE(d.empty());
  const int n = 4096;
  int up = 0;
  for (int i = 0; i < n; ++i) {
    const Vec2 u{(i + 0.5f) / n, float((i * 2654435761u) % 4096u) / 4096.0f};
    if (square_to_direction(d.sample(u).p).y > 0.5f) ++up;
  }
  return double(up) / n;
}

TEST(LightPathRecords, TeachAFloorToLookUpAtTheReflectorThatLightsIt) {
  const LoadedScene scene = test::scene_from_xml(kReflectorScene);
  GuidingTree tree(scene->bounds());
  GuidingRefinement whole;  // one region: every record in one distribution
  whole.spatial_threshold = 1e12;
  // Each round's records divide the quadrants that the next one records in.
  for (uint64_t pass = 0; pass < 6; ++pass) {
    ASSERT_TRUE(record_light_paths(*scene, tree, 50000, pass, 5, PathSettings{}, nullptr));
    tree.refine(whole, 1);
  }
  EXPECT_GT(share_looking_up(tree, {0, 0, 0}), 0.95);
}

// Paths of two segments reach nothing after a bounce: nothing recorded.
TEST(LightPathRecords, RecordNothingWhereNoLightArrivesAfterABounce) {
  const LoadedScene scene = test::scene_from_xml(kReflectorScene);
  GuidingTree tree(scene->bounds());
  PathSettings direct;
  direct.max_depth = 2;
  ASSERT_TRUE(record_light_paths(*scene, tree, 20000, 0, 5, direct, nullptr));
  GuidingRefinement whole;
  whole.spatial_threshold = 1e12;
  tree.refine(whole, 1);
  for (int b = 0; b < kNormalBuckets; ++b) EXPECT_TRUE(tree.region_at({0, 0, 0}).guides[b].sampling.empty()) << b;
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
