// Moving transforms: the parts a key splits into rebuild it, and the
// interpolation between keys moves each part as its own closed form says.

#include "core/math/animated_transform.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

void expect_matrix_near(const Matrix4& a, const Matrix4& b, double tolerance) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(a.m[i][j], b.m[i][j], tolerance) << "entry " << i << ", " << j;
}

TEST(TransformParts, RebuildRandomAffineMapsWithShearAndReflection) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-2, 2);
  for (int trial = 0; trial < 200; ++trial) {
    Matrix4 m = Matrix4::identity();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 4; ++j) m.m[i][j] = u(rng);
    const Transform t(m);
    const TransformParts parts = TransformParts::of(t);
    expect_matrix_near(parts.transform().matrix(), m, 1e-12);
    EXPECT_NEAR(parts.q[0] * parts.q[0] + parts.q[1] * parts.q[1] + parts.q[2] * parts.q[2] + parts.q[3] * parts.q[3],
                1, 1e-12);
    EXPECT_EQ(parts.s[1][0], 0);
    EXPECT_EQ(parts.s[2][0], 0);
    EXPECT_EQ(parts.s[2][1], 0);
  }
}

TEST(TransformParts, RefusesSingularMaps) {
  EXPECT_THROW(TransformParts::of(Transform(Transform::scale({1, 0, 1}).matrix(), Matrix4::identity())),
               std::invalid_argument);
}

// Halfway between a quarter turn about z and none, with a translation and
// a scale each growing linearly: an eighth of a turn, the means of the
// translations and of the scales.
TEST(AnimatedTransform, InterpolatesRotationAlongTheArcAndTheRestLinearly) {
  const Transform start = Transform::translate({1, 0, 0}) * Transform::scale({1, 1, 1});
  const Transform end =
      Transform::translate({3, 2, 0}) * Transform::rotate({0, 0, 1}, 90) * Transform::scale({2, 3, 1});
  const AnimatedTransform motion({start, end});
  const Transform half = motion.at(0.5);
  const Transform expected =
      Transform::translate({2, 1, 0}) * Transform::rotate({0, 0, 1}, 45) * Transform::scale({1.5, 2, 1});
  expect_matrix_near(half.matrix(), expected.matrix(), 1e-12);
  expect_matrix_near(motion.at(0).matrix(), start.matrix(), 1e-12);
  expect_matrix_near(motion.at(1).matrix(), end.matrix(), 1e-12);
  // Outside the shutter the nearest key holds.
  expect_matrix_near(motion.at(2).matrix(), end.matrix(), 1e-12);
}

// Three keys turning 170 degrees each way: the second leg takes the short
// way back, not the long way round, and each leg's middle is its mean.
TEST(AnimatedTransform, TakesEachLegTheShortWayAndKeepsItsKeys) {
  const AnimatedTransform motion(
      {Transform::rotate({0, 1, 0}, 0), Transform::rotate({0, 1, 0}, 170), Transform::rotate({0, 1, 0}, 0)});
  expect_matrix_near(motion.at(0.25).matrix(), Transform::rotate({0, 1, 0}, 85).matrix(), 1e-12);
  expect_matrix_near(motion.at(0.5).matrix(), Transform::rotate({0, 1, 0}, 170).matrix(), 1e-12);
  expect_matrix_near(motion.at(0.75).matrix(), Transform::rotate({0, 1, 0}, 85).matrix(), 1e-12);
}

// Keys that turn and move a shared scale keep the motion rigid; the first
// key that stretches or shears is named (counted from 1).
TEST(AnimatedTransform, NamesTheFirstKeyThatRescales) {
  const Transform scale = Transform::scale({2, 1, 0.5f});
  const Transform turned = Transform::translate({1, 2, 3}) * Transform::rotate({0, 0, 1}, 70) * scale;
  EXPECT_EQ(AnimatedTransform({scale, turned, Transform::rotate({1, 0, 0}, 30) * scale}).first_rescaled_key(), 0u);
  EXPECT_EQ(AnimatedTransform({scale, turned, turned * Transform::scale({1, 1.01f, 1})}).first_rescaled_key(), 3u);
  EXPECT_EQ(AnimatedTransform({scale, Transform::scale({2, 1, 0.6f}), scale}).first_rescaled_key(), 2u);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
