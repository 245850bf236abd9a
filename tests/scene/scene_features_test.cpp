// The scene summary the integrators plan their work from: lobes, lights,
// textures, camera, and above all whether caustic paths are possible.

#include "core/scene/scene_features.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/bsdf/bsdf.h"
#include "core/loader/scene_loader.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using testing::HasSubstr;

LoadedScene cornell(const std::string& name) {
  return load_scene(std::string(CAUSTICA_SOURCE_DIR) + "/scenes/" + name + ".xml", {{"res", "8"}});
}

TEST(SceneFeatures, DiffuseCornellBoxHasNoCausticPaths) {
  const auto scene = cornell("cornell-box");
  const SceneFeatures& f = scene->features();
  EXPECT_FALSE(f.caustic_paths);
  EXPECT_EQ(f.caustics_reason, "no surface has a delta lobe (mirror or smooth glass)");
  EXPECT_EQ(f.lobes, uint32_t(kDiffuseReflection));
  EXPECT_EQ(f.area_lights, 1);
  EXPECT_EQ(f.point_lights + f.environment_lights, 0);
  EXPECT_FALSE(f.textures);
  EXPECT_TRUE(f.pinhole);
}

TEST(SceneFeatures, GlassAndMirrorBoxesHaveCausticPaths) {
  for (const char* name : {"cornell-box-glass", "cornell-box-mirror"}) {
    const auto scene = cornell(name);
    EXPECT_TRUE(scene->features().caustic_paths) << name;
    EXPECT_THAT(scene->features().caustics_reason, HasSubstr("a light reaches a surface with a delta lobe: sphere"));
  }
  EXPECT_TRUE(cornell("cornell-box-glass")->features().lobes & kDeltaTransmission);
  EXPECT_TRUE(cornell("cornell-box-textured")->features().textures);
}

// Glass, but the only light is a point light shut away from it by a wall.
TEST(SceneFeatures, GlassHiddenFromThePointLightHasNoCausticPaths) {
  const std::string scene_text =
      "<scene version='3.0.0'><shape type='rectangle'><transform name='to_world'><scale value='3'/>"
      "</transform></shape><shape type='sphere'><point name='center' x='0' y='0' z='0.5'/>"
      "<float name='radius' value='0.3'/><bsdf type='dielectric'/></shape>"
      "<shape type='cube'><transform name='to_world'><scale x='0.05' y='2' z='2'/><translate x='1'/>"
      "</transform></shape><emitter type='point'><point name='position' x='$x' y='0' z='0.5'/></emitter></scene>";
  const auto hidden = load_scene_string(scene_text, "hidden.xml", {{"x", "2"}});
  EXPECT_FALSE(hidden->features().caustic_paths);
  EXPECT_EQ(hidden->features().caustics_reason, "no light reaches any of the 1 delta surfaces");
  const auto seen = load_scene_string(scene_text, "seen.xml", {{"x", "0.5"}});
  EXPECT_TRUE(seen->features().caustic_paths);
}

TEST(SceneFeatures, DescribedForInfo) {
  const std::string text = describe(cornell("cornell-box-glass")->features());
  EXPECT_THAT(text, HasSubstr("bsdf lobes: diffuse reflection, delta reflection, delta transmission\n"));
  EXPECT_THAT(text, HasSubstr("lights: 1 area, 0 point, 0 directional, 0 environment\n"));
  EXPECT_THAT(text, HasSubstr("camera: perspective (no lens to sample)\n"));
  EXPECT_THAT(text, HasSubstr("caustic paths: possible ("));
}

// The light tree where the choice can depend on the point: two emitters
// or more that it can bound.
TEST(SceneFeatures, LightTreeForTwoBoundedEmittersOrMore) {
  EXPECT_FALSE(cornell("cornell-box")->features().light_tree);
  EXPECT_THAT(describe(cornell("cornell-box")->features()),
              HasSubstr("light selection: by power (fewer than two emitters a light tree could bound, so the choice "
                        "would not depend on the point)\n"));
  const auto hall = cornell("many-lights");
  EXPECT_TRUE(hall->features().light_tree);
  EXPECT_THAT(describe(hall->features()), HasSubstr("light selection: light tree (124 emitters it can bound)\n"));
  // An environment and one point light: only one emitter in the tree.
  const auto one = test::scene_from_xml(
      "<scene version='3.0.0'><emitter type='constant'/><emitter type='point'><point name='position' x='0' y='1' "
      "z='0'/></emitter></scene>");
  EXPECT_FALSE(one->features().light_tree);
  SceneFeatures forced = one->features();
  force_light_tree(forced, true);
  EXPECT_THAT(describe(forced), HasSubstr("light selection: light tree (forced by the render settings)\n"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
