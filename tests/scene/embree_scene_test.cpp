#include "core/scene/embree_scene.h"

#include <gtest/gtest.h>

#include <random>

#include "core/sampling/warp.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

std::string scene_with(const std::string& shapes) { return "<scene version='3.0.0'>" + shapes + "</scene>"; }

TEST(EmbreeScene, RectangleHitDistanceAndNormal) {
  const auto scene = test::scene_from_xml(scene_with(
      "<shape type='rectangle'><transform name='to_world'><scale value='2'/><translate z='-3'/></transform></shape>"));
  const auto hit = scene->intersect({{0.5f, 0.5f, 0}, {0, 0, -1}});
  ASSERT_TRUE(hit);
  EXPECT_FLOAT_EQ(hit->t, 3);
  EXPECT_FLOAT_EQ(hit->p.z, -3);
  EXPECT_FLOAT_EQ(hit->ng.z, 1);
  EXPECT_FALSE(scene->intersect({{2.5f, 0, 0}, {0, 0, -1}}));     // outside the scaled square
  EXPECT_FALSE(scene->intersect({{0, 0, 0}, {0, 0, -1}, 2.5f}));  // t_max before the surface
}

TEST(EmbreeScene, SphereHitFromOutsideAndInside) {
  const auto scene =
      test::scene_from_xml(scene_with("<shape type='sphere'><point name='center' x='1' y='2' z='3'/>"
                                      "<float name='radius' value='0.5'/></shape>"));
  const auto outside = scene->intersect({{1, 2, 0}, {0, 0, 1}});
  ASSERT_TRUE(outside);
  EXPECT_NEAR(outside->t, 2.5f, 1e-6f);
  EXPECT_NEAR(outside->ng.z, -1, 1e-6f);
  EXPECT_NEAR(length(outside->p - Vec3(1, 2, 3)), 0.5f, 1e-6f);

  const auto inside = scene->intersect({{1, 2, 3}, {0, 1, 0}});
  ASSERT_TRUE(inside);
  EXPECT_NEAR(inside->t, 0.5f, 1e-6f);
  EXPECT_NEAR(inside->ng.y, 1, 1e-6f);  // normals point outward unless flipped
  EXPECT_FALSE(scene->intersect({{1, 3, 0}, {0, 0, 1}}));
}

TEST(EmbreeScene, SphereTransformAndFlippedNormals) {
  const auto scene = test::scene_from_xml(
      scene_with("<shape type='sphere'><boolean name='flip_normals' value='true'/>"
                 "<transform name='to_world'><scale value='2'/><translate x='5'/></transform></shape>"));
  const auto hit = scene->intersect({{5, 0, 0}, {1, 0, 0}});
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 2, 1e-6f);
  EXPECT_NEAR(hit->ng.x, -1, 1e-6f);
  EXPECT_NEAR(hit->shading.n.x, -1, 1e-6f);
}

TEST(EmbreeScene, NonUniformSphereScaleIsAnError) {
  EXPECT_NE(test::load_error(scene_with(
                "<shape type='sphere'><transform name='to_world'><scale x='1' y='2' z='1'/></transform></shape>")),
            "");
}

TEST(EmbreeScene, DiskAndCube) {
  const auto scene = test::scene_from_xml(
      scene_with("<shape type='disk'><transform name='to_world'><translate z='-1'/></transform></shape>"
                 "<shape type='cube'><transform name='to_world'><translate x='10'/></transform></shape>"));
  const auto disk = scene->intersect({{0.6f, 0.6f, 0}, {0, 0, -1}});
  ASSERT_TRUE(disk);
  EXPECT_NEAR(disk->t, 1, 1e-6f);
  EXPECT_FALSE(scene->intersect({{0.8f, 0.8f, 0}, {0, 0, -1}}));  // inside the square, outside the disk
  const auto cube = scene->intersect({{0, 0.5f, 0.5f}, {1, 0, 0}});
  ASSERT_TRUE(cube);
  EXPECT_NEAR(cube->t, 9, 1e-5f);
  EXPECT_NEAR(cube->ng.x, -1, 1e-6f);
  const auto from_inside = scene->intersect({{10, 0, 0}, {0, 0, 1}});
  ASSERT_TRUE(from_inside);
  EXPECT_NEAR(from_inside->t, 1, 1e-6f);
  EXPECT_NEAR(from_inside->ng.z, 1, 1e-6f);  // the outward normal, seen from inside
}

// Rays leaving sampled surface points must never find the surface they left
// (self-intersection, "acne"), at any scene scale and at grazing angles.
class SelfIntersection : public testing::TestWithParam<float> {};

TEST_P(SelfIntersection, LeavingRaysDoNotRehitTheirSurface) {
  const float scale = GetParam();
  const std::string s = std::to_string(scale), off = std::to_string(3 * scale);
  const auto scene = test::scene_from_xml(scene_with(
      "<shape type='sphere'><transform name='to_world'><scale value='" + s + "'/><translate x='" + off + "' y='" + off +
      "'/></transform></shape>"
      "<shape type='disk'><transform name='to_world'><rotate x='1' y='1' angle='33'/><scale value='" +
      s + "'/><translate x='-" + off +
      "'/></transform></shape>"
      "<shape type='rectangle'><transform name='to_world'><rotate x='1' angle='17'/><scale value='" +
      s + "'/><translate y='-" + off + "' z='" + off +
      "'/></transform></shape>"
      "<shape type='cube'><transform name='to_world'><rotate y='1' angle='40'/><scale value='" +
      s + "'/><translate x='" + off + "' z='-" + off + "'/></transform></shape>"));
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0, kOneMinusEpsilon);
  int failures = 0, tries = 0;
  for (const auto& shape : scene->shapes()) {
    for (int i = 0; i < 2000; ++i) {
      const PositionSample ps = shape->sample_position({u(rng), u(rng)});
      SurfaceInteraction si;
      si.p = ps.p;
      si.p_error = ps.p_error;
      si.ng = ps.n;
      // Directions away from the surface, biased toward grazing.
      Vec3 local = square_to_uniform_hemisphere({u(rng), u(rng)});
      if (i % 2) local.z *= 1e-3f;
      const Vec3 d = Frame::from_normal(ps.n).to_world(normalize(local));
      ++tries;
      const auto hit = scene->intersect(si.spawn(d));
      // Flat and convex shapes cannot be re-hit by a ray leaving outward.
      if (hit && hit->shape == shape.get()) ++failures;
      // Inward rays of the sphere must reach the far side (a chord of
      // length 2 r cos theta), not the point they started from.
      if (shape->kind() == "sphere") {
        const float chord = 2 * scale * abs_dot(d, ps.n);
        const auto inward = scene->intersect(si.spawn(-d));
        if (!inward || inward->t < 0.5f * chord) ++failures;
      }
    }
  }
  EXPECT_EQ(failures, 0) << "of " << tries << " rays at scale " << scale;
}

INSTANTIATE_TEST_SUITE_P(Scales, SelfIntersection, testing::Values(1e-3f, 1.0f, 1e4f));

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
