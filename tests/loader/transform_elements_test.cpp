// Each transform element of a scene file, and their order, changes where a
// shape is: a unit rectangle (the square [-1, 1]^2 at z = 0, normal +z)
// placed by one <transform> is probed by rays whose hits and misses are
// worked out here by hand, so that a loader ignoring or misreading any
// element (a uniform scale, an axis, an angle's sign, the order of steps)
// changes some answer.

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// A rectangle placed by `steps`, the camera at the origin (so render space
// is world space).
LoadedScene placed(const std::string& steps) {
  return test::scene_from_xml("<scene version='3.0.0'><shape type='rectangle'><transform name='to_world'>" + steps +
                              "</transform></shape></scene>");
}

// Where a ray from `from` along `d` meets the rectangle, if it does.
std::optional<SurfaceInteraction> probe(const LoadedScene& scene, Vec3 from, Vec3 d) {
  return scene->intersect({from, normalize(d)});
}

const Vec3 kDown{0, 0, -1};

TEST(TransformElements, UniformAndAxisScales) {
  const auto twice = placed("<scale value='2'/>");  // [-2, 2]^2
  EXPECT_TRUE(probe(twice, {1.5f, -1.5f, 1}, kDown));
  EXPECT_FALSE(probe(twice, {2.5f, 0, 1}, kDown));
  // Stood up in the x-z plane first, the uniform scale must stretch z too.
  const auto standing = placed("<rotate x='1' angle='90'/><scale value='2'/>");
  EXPECT_TRUE(probe(standing, {0, -5, 1.5f}, {0, 1, 0}));
  EXPECT_FALSE(probe(standing, {0, -5, 2.5f}, {0, 1, 0}));
  const auto stretched = placed("<scale x='3' y='0.5'/>");  // [-3, 3] x [-0.5, 0.5]
  EXPECT_TRUE(probe(stretched, {2.5f, 0.4f, 1}, kDown));
  EXPECT_FALSE(probe(stretched, {0, 0.7f, 1}, kDown));
  EXPECT_FALSE(probe(stretched, {3.2f, 0, 1}, kDown));
}

TEST(TransformElements, TranslateMovesEveryAxis) {
  const auto moved = placed("<translate x='1' y='2' z='3'/>");
  const auto hit = probe(moved, {1.9f, 2.9f, 10}, kDown);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->p.z, 3, 1e-5f);
  EXPECT_FALSE(probe(moved, {-0.1f, 2, 10}, kDown));
  EXPECT_FALSE(probe(moved, {1, 0.9f, 10}, kDown));
}

// A positive angle turns counter-clockwise looking down the axis: +z about
// +x by 90 degrees becomes -y, so the rectangle stands in the x-z plane
// facing -y; about +y by 90 degrees +z becomes +x.
TEST(TransformElements, RotateAboutEachAxisWithItsSign) {
  const auto about_x = placed("<rotate x='1' angle='90'/>");
  const auto a = probe(about_x, {0.5f, -5, 0.5f}, {0, 1, 0});
  ASSERT_TRUE(a);
  EXPECT_NEAR(a->p.y, 0, 1e-5f);
  EXPECT_NEAR(a->ng.y, -1, 1e-5f);
  const auto about_y = placed("<rotate y='1' angle='90'/>");
  const auto b = probe(about_y, {5, 0.5f, -0.5f}, {-1, 0, 0});
  ASSERT_TRUE(b);
  EXPECT_NEAR(b->ng.x, 1, 1e-5f);
  // About z the square turns in its own plane: 45 degrees reach a corner
  // sqrt(2) out along the x axis.
  const auto about_z = placed("<rotate z='1' angle='45'/>");
  EXPECT_TRUE(probe(about_z, {1.35f, 0, 1}, kDown));
  EXPECT_FALSE(probe(about_z, {0.95f, 0.95f, 1}, kDown));
}

TEST(TransformElements, MatrixIsRowMajorActingOnColumns) {
  // Scale x by 2 and move by (0, 5, 1): the last column is the translation.
  const auto m = placed("<matrix value='2 0 0 0  0 1 0 5  0 0 1 1  0 0 0 1'/>");
  const auto hit = probe(m, {1.8f, 5.9f, 10}, kDown);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->p.z, 1, 1e-5f);
  EXPECT_FALSE(probe(m, {0, 0, 10}, kDown));
}

// lookat on a shape points its local +z from origin toward target.
TEST(TransformElements, LookAtPointsTheNormal) {
  const auto faced = placed("<lookat origin='0, 0, 2' target='0, 3, 2' up='0, 0, 1'/>");
  const auto hit = probe(faced, {0.5f, 10, 2.5f}, {0, -1, 0});
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->p.y, 0, 1e-5f);
  EXPECT_NEAR(hit->ng.y, 1, 1e-5f);
}

// Steps apply in the order written: scale then translate spans x in
// [-1, 3]; translate then scale spans [0, 4].
TEST(TransformElements, StepsApplyInTheOrderWritten) {
  const auto scale_first = placed("<scale x='2'/><translate x='1'/>");
  const auto translate_first = placed("<translate x='1'/><scale x='2'/>");
  EXPECT_TRUE(probe(scale_first, {-0.5f, 0, 1}, kDown));
  EXPECT_FALSE(probe(translate_first, {-0.5f, 0, 1}, kDown));
  EXPECT_FALSE(probe(scale_first, {3.5f, 0, 1}, kDown));
  EXPECT_TRUE(probe(translate_first, {3.5f, 0, 1}, kDown));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
