// The learned directional distribution: its sampling against its density
// (chi-square), its density against the recorded energies (an oracle that
// walks the shape's rectangles itself), the cylindrical map's area, the
// recorder's sums and the refinement of its shape.

#include "integrators/path/guiding/directional_quadtree.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "tests/support/chi2.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// Energies recorded at points drawn from a lopsided density: most near
// (0.8, 0.3), some spread uniformly, none in the square's top-left eighth.
DirectionalDistribution lopsided(int records, double threshold = 0.01, int passes = 4) {
  std::mt19937 rng(7);
  std::normal_distribution<float> near(0, 0.05f);
  std::uniform_real_distribution<float> any(0, 1);
  QuadtreeShape shape;
  DirectionalDistribution d;
  for (int pass = 0; pass < passes; ++pass) {
    DirectionalRecorder recorder(shape);
    for (int i = 0; i < records; ++i) {
      Vec2 p = i % 4 == 0 ? Vec2{any(rng), any(rng)} : Vec2{0.8f + near(rng), 0.3f + near(rng)};
      p = {std::clamp(p.x, 0.0f, 0.999f), std::clamp(p.y, 0.0f, 0.999f)};
      if (p.x < 0.5f && p.y >= 0.75f) continue;
      recorder.record(p, 1 + p.x);
    }
    d = recorder.distribution();
    shape = refined_shape(d, threshold, 20);
  }
  return d;
}

// The density at p by walking the shape's rectangles: a leaf quadrant's
// energy over the total, divided by its area.
double oracle_pdf(const DirectionalDistribution& d, Vec2 p) {
  double x0 = 0, y0 = 0, size = 1;
  uint32_t node = 0;
  const double total = d.total();
  for (;;) {
    size /= 2;
    const int qx = p.x >= x0 + size ? 1 : 0, qy = p.y >= y0 + size ? 1 : 0;
    x0 += qx * size;
    y0 += qy * size;
    const int q = qx + 2 * qy;
    const uint32_t child = d.shape().children[node][q];
    if (child == 0) return d.energy(node)[q] / total / (size * size);
    node = child;
  }
}

TEST(DirectionalDistribution, SamplesFollowItsDensity) {
  const DirectionalDistribution d = lopsided(20000);
  ASSERT_GT(d.shape().nodes(), 10u);
  test::Chi2Options options;
  options.bins_u = options.bins_v = 64;
  const auto result =
      test::chi2_test_rect([&](test::UniformSource& u) -> std::optional<Vec2> { return d.sample(u.next_2d()).p; },
                           [&](const Vec2& p) { return double(d.pdf(p)); }, {}, options);
  EXPECT_GT(result.p_value, 0.01) << result.report;
}

TEST(DirectionalDistribution, DensityIsTheRecordedShareOverArea) {
  const DirectionalDistribution d = lopsided(20000);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> any(0, 1);
  for (int i = 0; i < 20000; ++i) {
    const Vec2 p{any(rng), any(rng)};
    EXPECT_NEAR(d.pdf(p), oracle_pdf(d, p), 1e-4 * oracle_pdf(d, p)) << p.x << ", " << p.y;
  }
  EXPECT_EQ(d.pdf({0.2f, 0.9f}), 0) << "no energy was recorded there";
  EXPECT_NEAR(test::integrate_rect([&](const Vec2& p) { return double(d.pdf(p)); }, {}, 256, 256), 1, 1e-3);
}

TEST(DirectionalDistribution, SampleDensityEqualsDensityAtThePoint) {
  const DirectionalDistribution d = lopsided(20000);
  test::UniformSource u(5);
  for (int i = 0; i < 100000; ++i) {
    const auto s = d.sample(u.next_2d());
    ASSERT_GT(s.pdf, 0);
    ASSERT_EQ(s.pdf, d.pdf(s.p)) << s.p.x << ", " << s.p.y;
  }
}

// Near its sample, within a leaf or beyond it, the density read from a
// sample is the density at the point.
TEST(DirectionalDistribution, DensityNearASampleIsTheDensityThere) {
  const DirectionalDistribution d = lopsided(20000);
  test::UniformSource u(6);
  int beyond = 0;
  for (int i = 0; i < 100000; ++i) {
    const auto s = d.sample(u.next_2d());
    ASSERT_GE(s.p.x, s.leaf.x);
    ASSERT_LT(s.p.x, s.leaf.x + s.leaf_size);
    ASSERT_GE(s.p.y, s.leaf.y);
    ASSERT_LT(s.p.y, s.leaf.y + s.leaf_size);
    const float step = s.leaf_size * (u.next_1d() - 0.5f);
    const Vec2 near{std::clamp(s.p.x + step, 0.0f, 0.99999f), std::clamp(s.p.y - step, 0.0f, 0.99999f)};
    if (d.pdf(near) != s.pdf) ++beyond;
    ASSERT_EQ(d.pdf_near(s, near), d.pdf(near)) << near.x << ", " << near.y;
  }
  EXPECT_GT(beyond, 1000);
}

TEST(DirectionalDistribution, EmptyIsUniform) {
  const DirectionalDistribution d;
  EXPECT_TRUE(d.empty());
  EXPECT_EQ(d.pdf({0.3f, 0.7f}), 1);
  const auto s = d.sample({0.25f, 0.5f});
  EXPECT_EQ(s.p.x, 0.25f);
  EXPECT_EQ(s.pdf, 1);
}

TEST(DirectionalDistribution, OverTheSphereFollowsItsDensity) {
  const DirectionalDistribution d = lopsided(20000);
  const auto result = test::chi2_test_sphere(
      [&](test::UniformSource& u) -> std::optional<Vec3> { return square_to_direction(d.sample(u.next_2d()).p); },
      [&](const Vec3& w) { return double(d.pdf(direction_to_square(w))) / (4 * M_PI); });
  EXPECT_GT(result.p_value, 0.01) << result.report;
}

TEST(CylindricalMap, RoundTripsAndKeepsArea) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> any(0, 1);
  for (int i = 0; i < 10000; ++i) {
    const Vec2 p{any(rng), any(rng)};
    const Vec3 w = square_to_direction(p);
    EXPECT_NEAR(length(w), 1, 1e-5);
    const Vec2 back = direction_to_square(w);
    EXPECT_NEAR(back.x, p.x, 2e-5);
    EXPECT_NEAR(std::min(std::abs(back.y - p.y), 1 - std::abs(back.y - p.y)), 0, 2e-5);
  }
  // A band of the square of height h covers the share h of the sphere:
  // z = 2x - 1 is uniform over the sphere (Archimedes).
  EXPECT_NEAR(square_to_direction({0.75f, 0.25f}).z, 0.5f, 1e-6);
  EXPECT_NEAR(square_to_direction({0.5f, 0.25f}).y, 1, 1e-6);
}

TEST(DirectionalRecorder, SumsWhatFallsInEachQuadrantInAnyOrder) {
  QuadtreeShape shape;
  shape.children[0][1] = 1;  // the lower right quadrant divided once
  shape.children.push_back({0, 0, 0, 0});
  std::mt19937 rng(2);
  std::uniform_real_distribution<float> any(0, 1);
  std::vector<std::pair<Vec2, double>> records;
  for (int i = 0; i < 5000; ++i) records.push_back({{any(rng), any(rng)}, std::ldexp(any(rng), i % 40 - 20)});
  DirectionalRecorder forward(shape), backward(shape);
  for (const auto& [p, e] : records) forward.record(p, e);
  for (auto it = records.rbegin(); it != records.rend(); ++it) backward.record(it->first, it->second);
  const DirectionalDistribution a = forward.distribution(), b = backward.distribution();
  // Oracle: the sums by brute force over the quadrants' rectangles.
  std::array<double, 4> root{}, sub{};
  for (const auto& [p, e] : records) {
    const int q = (p.x >= 0.5f) + 2 * (p.y >= 0.5f);
    root[q] += e;
    if (q == 1) sub[(p.x >= 0.75f) + 2 * (p.y >= 0.25f)] += e;
  }
  for (int q = 0; q < 4; ++q) {
    EXPECT_EQ(a.energy(0)[q], b.energy(0)[q]);
    EXPECT_EQ(a.energy(1)[q], b.energy(1)[q]);
    EXPECT_NEAR(a.energy(0)[q], root[q], 1e-9 * root[q]);
    EXPECT_NEAR(a.energy(1)[q], sub[q], 1e-9 * sub[q]);
  }
}

// A spread record covers a square the size of its leaf quadrant: here the
// root's quadrants (1/2 wide), so a record at (0.5, 0.3) puts half its
// energy on each side of x = 0.5, all below y = 0.5 but for the part of
// the square above it (0.3 + 0.25 - 0.5 = 0.05 of 0.5); one at the corner
// keeps only the quarter of its square inside the unit square.
TEST(DirectionalRecorder, SpreadsARecordOverItsQuadrantsNeighbourhood) {
  DirectionalRecorder recorder;
  recorder.record_spread({0.5f, 0.3f}, 1);
  const DirectionalDistribution d = recorder.distribution();
  EXPECT_NEAR(d.energy(0)[0], 0.5 * 0.9, 1e-6);
  EXPECT_NEAR(d.energy(0)[1], 0.5 * 0.9, 1e-6);
  EXPECT_NEAR(d.energy(0)[2], 0.5 * 0.1, 1e-6);
  EXPECT_NEAR(d.energy(0)[3], 0.5 * 0.1, 1e-6);
  DirectionalRecorder corner;
  corner.record_spread({0.0f, 0.0f}, 1);
  EXPECT_NEAR(corner.distribution().total(), 0.25, 1e-9);
  // Deeper quadrants spread less: a divided quadrant's record stays in it
  // when its square (1/4 wide) does not reach the edge.
  QuadtreeShape shape;
  shape.children[0][0] = 1;
  shape.children.push_back({0, 0, 0, 0});
  DirectionalRecorder deep(shape);
  deep.record_spread({0.125f, 0.125f}, 2);
  const DirectionalDistribution e = deep.distribution();
  EXPECT_NEAR(e.energy(1)[0], 2, 1e-9);
  EXPECT_EQ(e.energy(0)[1] + e.energy(0)[2] + e.energy(0)[3], 0);
}

TEST(RefinedShape, DividesQuadrantsAboveTheThresholdDownToTheDepthLimit) {
  QuadtreeShape root;
  // All energy in quadrant 0, and within it all in its quadrant 3.
  QuadtreeShape shape = root;
  shape.children[0][0] = 1;
  shape.children.push_back({0, 0, 0, 0});
  const DirectionalDistribution d(shape, {{{1, 0, 0, 0}}, {{0, 0, 0, 1}}});
  const QuadtreeShape refined = refined_shape(d, 0.3, 20);
  // Quadrant 0 (share 1) divides; its quadrant 3 (share 1) divides into
  // four of share 1/4 each, which is below 0.3: they stay leaves.
  ASSERT_EQ(refined.nodes(), 3u);
  EXPECT_NE(refined.children[0][0], 0u);
  const uint32_t a = refined.children[0][0];
  EXPECT_NE(refined.children[a][3], 0u);
  EXPECT_EQ(refined.children[a][0], 0u);
  EXPECT_EQ(refined.children[refined.children[a][3]], (std::array<uint32_t, 4>{0, 0, 0, 0}));
  // With a lower threshold the evenly spread quarters divide again, down to the limit.
  EXPECT_EQ(refined_shape(d, 0.2, 20).nodes(), 7u);
  EXPECT_EQ(refined_shape(d, 1e-9, 3).nodes(), 3u);
  EXPECT_EQ(refined_shape(d, 1e-9, 4).nodes(), 7u);
  EXPECT_EQ(refined_shape(DirectionalDistribution(), 0.01, 20).nodes(), 1u);
}

TEST(FixedPointSum, IsTheSameInAnyOrderAndExactToItsResolution) {
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> any(0, 1);
  std::vector<double> terms;
  for (int i = 0; i < 10000; ++i) terms.push_back(std::ldexp(any(rng), int(rng() % 60) - 30));
  FixedPointSum forward, backward;
  long double exact = 0;
  for (double t : terms) {
    forward.add(t);
    exact += t;
  }
  for (auto it = terms.rbegin(); it != terms.rend(); ++it) backward.add(*it);
  EXPECT_EQ(forward.value(), backward.value());
  EXPECT_NEAR(forward.value(), double(exact), 1e-12 * double(exact));
  FixedPointSum carries;
  for (int i = 0; i < 3; ++i) carries.add(0.75);  // 2.25: the fractions carry into the whole part
  EXPECT_EQ(carries.value(), 2.25);
  FixedPointSum ignored;
  ignored.add(-1);
  ignored.add(std::nan(""));
  EXPECT_EQ(ignored.value(), 0);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
