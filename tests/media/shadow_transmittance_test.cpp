// Shadow rays through index-matched (null) boundaries: the transmittance of
// the medium they bound is Beer-Lambert's over the length inside, and a
// segment that ends within rounding distance past a boundary ends there.

#include "core/transport/shadow_transmittance.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/math/next_float.h"
#include "core/scene/scene.h"
#include "core/shapes/shape.h"
#include "tests/support/samplers.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// A null cube [-1, 1]^3 filled with a medium of extinction 0.5, and a light
// far away so that the scene has one.
struct FogCube {
  LoadedScene scene = test::scene_from_xml(
      "<scene version='3.0.0'>"
      "<medium type='homogeneous' id='fog'><float name='sigma_t' value='0.5'/></medium>"
      "<shape type='cube'><ref name='interior' id='fog'/></shape>"
      "<shape type='sphere'><transform name='to_world'><translate z='20'/></transform>"
      "<emitter type='area'><rgb name='radiance' value='1'/></emitter></shape></scene>");
  std::unique_ptr<Sampler> sampler = test::make_sampler("independent");

  const Medium* fog() const {
    for (const auto& shape : scene->shapes())
      if (shape->bounds_media()) return shape->interior();
    return nullptr;
  }
  Color transmittance(const Ray& ray, const Medium* start) {
    return shadow_transmittance(*scene, ray, start, *sampler);
  }
};

TEST(ShadowTransmittance, BeerLambertAcrossANullBoundedMedium) {
  FogCube cube;
  ASSERT_NE(cube.fog(), nullptr);
  // From outside through the whole cube: 2 units inside.
  EXPECT_NEAR(cube.transmittance({{0.25f, 0.1f, -3}, {0, 0, 6}, 1}, nullptr).g, std::exp(-1.0), 1e-5);
  // From inside to a point outside: 1.5 units inside.
  EXPECT_NEAR(cube.transmittance({{0, 0.3f, -0.5f}, {0, 0, 4}, 1}, cube.fog()).g, std::exp(-0.75), 1e-5);
  // Out of the cube along an unnormalised direction, to infinity (away from
  // the light): 0.5 inside.
  EXPECT_NEAR(cube.transmittance({{0.5f, 0, 0}, {3, 0, 0}, kInfinity}, cube.fog()).g, std::exp(-0.25), 1e-5);
}

TEST(ShadowTransmittance, EndsWithinRoundingPastABoundary) {
  FogCube cube;
  // Segments that end a few floats past the cube's far face, where stepping
  // off the face lands beyond the end. Each returns, with 2 units inside.
  float z = 1;
  for (int step = 0; step < 64; ++step, z = next_float_up(z)) {
    const Ray ray{{0.2f, -0.3f, -2}, {0, 0, z + 2}, 1};
    EXPECT_NEAR(cube.transmittance(ray, nullptr).g, std::exp(-1.0), 1e-5) << "end z = 1 + " << step << " ulps";
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
