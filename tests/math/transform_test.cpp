#include "core/math/transform.h"

#include <gtest/gtest.h>

#include "core/math/frame.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

void expect_near(Vec3 a, Vec3 b, float tol = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

TEST(Transform, ComposesInApplicationOrder) {
  const Transform t = Transform::translate({1, 2, 3}) * Transform::scale({2, 2, 2});
  expect_near(t.point({1, 1, 1}), {3, 4, 5});
  expect_near(t.vector({1, 1, 1}), {2, 2, 2});
  expect_near(t.inverse().point({3, 4, 5}), {1, 1, 1});
}

TEST(Transform, RotatesCounterClockwiseAboutAxis) {
  const Transform r = Transform::rotate({0, 0, 1}, 90);
  expect_near(r.point({1, 0, 0}), {0, 1, 0});
  expect_near(r.inverse().point({0, 1, 0}), {1, 0, 0});
}

TEST(Transform, NormalsStayPerpendicularUnderNonUniformScale) {
  const Transform s = Transform::scale({4, 1, 1});
  const Vec3 tangent = s.vector(normalize(Vec3(1, -1, 0)));
  const Vec3 n = s.normal(normalize(Vec3(1, 1, 0)));
  EXPECT_NEAR(dot(tangent, n), 0, 1e-6f);
}

TEST(Transform, LookAtPointsLocalZAtTargetAndXLeft) {
  const Transform t = Transform::look_at({0, 0, 4}, {0, 0, 0}, {0, 1, 0});
  expect_near(t.point({0, 0, 0}), {0, 0, 4});
  expect_near(t.vector({0, 0, 1}), {0, 0, -1});
  expect_near(t.vector({0, 1, 0}), {0, 1, 0});
  // Looking down -z with y up, the viewer's left is -x.
  expect_near(t.vector({1, 0, 0}), {-1, 0, 0});
}

TEST(Transform, SingularMatrixIsRejected) {
  Matrix4 m = Matrix4::identity();
  m.m[2][2] = 0;
  EXPECT_THROW(Transform{m}, std::invalid_argument);
}

TEST(Transform, InverseIsAccurateAtHugeScale) {
  const Transform t = Transform::translate({1e6f, -3e5f, 2e4f}) * Transform::scale({1e3f, 1e3f, 1e3f});
  expect_near(t.inverse().point(t.point({0.25f, 0.5f, -0.75f})), {0.25f, 0.5f, -0.75f}, 1e-3f);
}

// Composed in double, a far translation and its way back keep a small
// offset exactly; in float, 1e7 + 0.3 would already have lost it.
TEST(Transform, ComposesInDoubleBeforeRoundingToFloat) {
  const Transform there = Transform::scale({1e-3, 1e-3, 1e-3});
  const Transform moved = Transform::translate({-12345678.9, 0, 0}) * Transform::translate({12345678.9, 0, 0}) * there;
  EXPECT_EQ(moved.point(Vec3(300, 0, 0)).x, 0.3f);
  EXPECT_EQ(moved.point_double({0.1, 0, 0}).x, 1e-4);
  const Transform camera = Transform::look_at({1e7 + 0.5, 2, 3}, {1e7 + 0.5, 2, 4}, {0, 1, 0});
  EXPECT_EQ(camera.point_double({0, 0, 0}).x, 1e7 + 0.5);
}

TEST(Frame, IsOrthonormalForEveryNormal) {
  for (Vec3 n :
       {Vec3(0, 0, 1), Vec3(0, 0, -1), Vec3(1, 0, 0), normalize(Vec3(1, 2, -3)), normalize(Vec3(1e-8f, 0, -1))}) {
    const Frame f = Frame::from_normal(n);
    EXPECT_NEAR(dot(f.s, f.t), 0, 1e-6f);
    EXPECT_NEAR(dot(f.s, f.n), 0, 1e-6f);
    EXPECT_NEAR(length(f.s), 1, 1e-6f);
    EXPECT_NEAR(length(f.t), 1, 1e-6f);
    expect_near(cross(f.s, f.t), n);
    expect_near(f.to_world(f.to_local({0.3f, -0.2f, 0.9f})), {0.3f, -0.2f, 0.9f});
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
