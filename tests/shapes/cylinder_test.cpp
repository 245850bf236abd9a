// cylinder: hits worked by hand on the side (from outside, from inside,
// past the open ends), its area and samples, and the refusals. Its solid
// (with the ends) is checked as a csg operand in csg_test.cpp.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "core/math/constants.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using testing::HasSubstr;

// Radius 0.5 from (0, 0, 0) to (0, 0, 2), written as radius 0.25 from
// (0, 0, 0) to (0, 0, 1) scaled by 2.
const char* kCylinder =
    "<scene version='3.0.0'><shape type='cylinder'><float name='radius' value='0.25'/>"
    "<transform name='to_world'><scale value='2'/></transform></shape></scene>";

TEST(CylinderShape, HitsItsSideOnlyBetweenTheEnds) {
  const auto loaded = test::scene_from_xml(kCylinder);
  const Scene& scene = *loaded.scene;
  const auto from_outside = scene.intersect({{2, 0, 1}, {-1, 0, 0}, kInfinity});
  ASSERT_TRUE(from_outside);
  EXPECT_NEAR(from_outside->t, 1.5f, 1e-6f);
  EXPECT_NEAR(from_outside->ng.x, 1, 1e-6f);
  EXPECT_NEAR(from_outside->uv.y, 0.5f, 1e-6f);
  const auto from_inside = scene.intersect({{0, 0, 1.5f}, {0, 0.8f, 0.6f}, kInfinity});
  ASSERT_TRUE(from_inside);
  EXPECT_NEAR(from_inside->p.y, 0.5f, 1e-6f);
  EXPECT_NEAR(from_inside->p.z, 1.5f + 0.6f * 0.5f / 0.8f, 1e-6f);
  EXPECT_NEAR(from_inside->ng.y, 1, 1e-6f);
  // Along the axis through the open ends, and past the end at z = 2.
  EXPECT_FALSE(scene.intersect({{0, 0, -1}, {0, 0, 1}, kInfinity}));
  EXPECT_FALSE(scene.intersect({{2, 0, 2.5f}, {-1, 0, 0}, kInfinity}));
  // A ray leaving the side never finds it again.
  EXPECT_FALSE(scene.intersect(from_outside->spawn({1, 0, 0})));
}

TEST(CylinderShape, SamplesItsSideUniformly) {
  const auto loaded = test::scene_from_xml(kCylinder);
  const Shape& shape = *loaded.scene->shapes().front();
  EXPECT_NEAR(shape.area(), 2 * kPi * 0.5 * 2, 1e-5);
  for (float u : {0.0f, 0.3f, 0.99f}) {
    const PositionSample ps = shape.sample_position({u, 1 - u});
    EXPECT_NEAR(std::hypot(ps.p.x, ps.p.y), 0.5f, 1e-6f);
    EXPECT_NEAR(ps.p.z, 2 * (1 - u), 1e-5f);
    EXPECT_NEAR(dot(ps.n, Vec3(ps.p.x, ps.p.y, 0)), 0.5f, 1e-6f);
    EXPECT_FLOAT_EQ(ps.pdf, 1 / shape.area());
  }
}

TEST(CylinderShape, RefusesBadParameters) {
  const auto error = [](const std::string& inside) {
    return test::load_error("<scene version='3.0.0'>\n<shape type='cylinder'>" + inside + "</shape></scene>");
  };
  EXPECT_THAT(error("<float name='radius' value='0'/>"),
              HasSubstr("parameter 'radius' of shape 'cylinder': must be positive"));
  EXPECT_THAT(error("<point name='p1' x='0' y='0' z='0'/>"),
              HasSubstr("parameter 'p1' of shape 'cylinder': must differ from p0"));
  EXPECT_THAT(error("<transform name='to_world'><scale x='1' y='2' z='1'/></transform>"),
              HasSubstr("a cylinder's to_world may only translate, rotate and scale uniformly"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
