#include "core/sampling/warp.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/math/constants.h"
#include "core/sampling/discrete_distribution.h"
#include "tests/support/chi2.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using test::Chi2Options;
using test::Chi2Result;
using test::Rect;
using test::UniformSource;

// The chi-square tests below that must pass. Each runs at the Sidak-corrected
// level, so that a correct implementation fails any one of them with
// probability 1% in all (the seeds are fixed, so in practice never).
constexpr int kChi2TestCount = 9;
const double kAlpha = test::sidak_alpha(0.01, kChi2TestCount);

constexpr double kTwoPi = 2 * std::numbers::pi;
constexpr float kTinyConeCos = 0.999999f;

std::string str(Vec2 v) {
  std::ostringstream s;
  s.precision(9);
  s << "(" << v.x << ", " << v.y << ")";
  return s.str();
}

std::string str(Vec3 v) {
  std::ostringstream s;
  s.precision(9);
  s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
  return s.str();
}

// The corners and centre of the unit square, where maps tend to break, then
// random points.
const std::vector<Vec2>& square_points() {
  static const std::vector<Vec2> points = [] {
    std::vector<Vec2> p = {{0, 0},
                           {kOneMinusEpsilon, 0},
                           {0, kOneMinusEpsilon},
                           {kOneMinusEpsilon, kOneMinusEpsilon},
                           {0.5f, 0.5f},
                           {0.5f, 0},
                           {0, 0.5f},
                           {0.25f, 0.75f}};
    UniformSource source(7);
    for (int i = 0; i < 100000; ++i) p.push_back(source.next_2d());
    return p;
  }();
  return points;
}

// Checks in_domain on the image of every test point, reporting the first miss.
template <typename Warp, typename InDomain>
::testing::AssertionResult maps_into_domain(Warp warp, InDomain in_domain) {
  for (Vec2 u : square_points()) {
    const auto s = warp(u);
    if (!in_domain(s)) return ::testing::AssertionFailure() << "u = " << str(u) << " maps to " << str(s);
  }
  return ::testing::AssertionSuccess();
}

bool is_unit(Vec3 w) { return std::abs(length(w) - 1) < 1e-5f; }

// 1 - cos(theta) of a unit direction, accurate even next to the pole.
double versine(Vec3 w) {
  const double x = w.x, y = w.y, z = w.z;
  return (x * x + y * y) / (1 + z);
}

template <typename Warp>
test::DirectionSampler direction_sampler(Warp warp) {
  return [warp](UniformSource& s) -> std::optional<Vec3> { return warp(s.next_2d()); };
}

template <typename Warp>
test::PointSampler point_sampler(Warp warp) {
  return [warp](UniformSource& s) -> std::optional<Vec2> { return warp(s.next_2d()); };
}

double hemisphere_pdf(const Vec3& w) { return w.z > 0 ? uniform_hemisphere_pdf() : 0; }
double cosine_pdf(const Vec3& w) { return cosine_hemisphere_pdf(w.z); }
double sphere_pdf(const Vec3&) { return uniform_sphere_pdf(); }
double disk_pdf(const Vec2& p) { return p.x * p.x + p.y * p.y <= 1 ? uniform_disk_pdf() : 0; }
double triangle_pdf(const Vec2& b) { return b.x + b.y <= 1 ? 2 : 0; }

Chi2Options options(uint32_t seed, int bins_u, int bins_v) {
  Chi2Options o;
  o.seed = seed;
  o.bins_u = bins_u;
  o.bins_v = bins_v;
  return o;
}

const Rect kDiskSquare{-1, 1, -1, 1};
const Rect kUnitSquare{0, 1, 0, 1};

TEST(UniformHemisphere, PdfIntegratesToOne) { EXPECT_NEAR(test::integrate_sphere(hemisphere_pdf), 1, 1e-3); }

TEST(UniformHemisphere, SamplesLieOnUpperHemisphere) {
  EXPECT_TRUE(maps_into_domain(square_to_uniform_hemisphere, [](Vec3 w) { return is_unit(w) && w.z >= 0; }));
}

TEST(UniformHemisphere, SamplesFollowPdf) {
  const Chi2Result r =
      test::chi2_test_sphere(direction_sampler(square_to_uniform_hemisphere), hemisphere_pdf, options(101, 40, 80));
  EXPECT_GT(r.p_value, kAlpha) << r.report;
}

TEST(CosineHemisphere, PdfIntegratesToOne) { EXPECT_NEAR(test::integrate_sphere(cosine_pdf), 1, 1e-3); }

TEST(CosineHemisphere, PdfVanishesBelowHorizon) {
  EXPECT_EQ(cosine_hemisphere_pdf(0), 0);
  EXPECT_EQ(cosine_hemisphere_pdf(-0.5f), 0);
  EXPECT_FLOAT_EQ(cosine_hemisphere_pdf(1), kInvPi);
}

TEST(CosineHemisphere, SamplesLieOnUpperHemisphere) {
  EXPECT_TRUE(maps_into_domain(square_to_cosine_hemisphere, [](Vec3 w) { return is_unit(w) && w.z >= 0; }));
}

TEST(CosineHemisphere, SamplesFollowPdf) {
  const Chi2Result r =
      test::chi2_test_sphere(direction_sampler(square_to_cosine_hemisphere), cosine_pdf, options(102, 40, 80));
  EXPECT_GT(r.p_value, kAlpha) << r.report;
}

TEST(UniformSphere, PdfIntegratesToOne) { EXPECT_NEAR(test::integrate_sphere(sphere_pdf), 1, 1e-3); }

TEST(UniformSphere, SamplesAreUnitVectors) { EXPECT_TRUE(maps_into_domain(square_to_uniform_sphere, is_unit)); }

TEST(UniformSphere, SamplesFollowPdf) {
  const Chi2Result r =
      test::chi2_test_sphere(direction_sampler(square_to_uniform_sphere), sphere_pdf, options(103, 40, 80));
  EXPECT_GT(r.p_value, kAlpha) << r.report;
}

TEST(ConcentricDisk, PdfIntegratesToOne) { EXPECT_NEAR(test::integrate_rect(disk_pdf, kDiskSquare), 1, 1e-3); }

TEST(ConcentricDisk, SamplesLieInUnitDisk) {
  EXPECT_TRUE(
      maps_into_domain(square_to_uniform_disk_concentric, [](Vec2 p) { return p.x * p.x + p.y * p.y <= 1 + 1e-6f; }));
  const Vec2 centre = square_to_uniform_disk_concentric({0.5f, 0.5f});
  EXPECT_EQ(centre.x, 0);
  EXPECT_EQ(centre.y, 0);
}

TEST(ConcentricDisk, SamplesFollowPdf) {
  const Chi2Result r = test::chi2_test_rect(point_sampler(square_to_uniform_disk_concentric), disk_pdf, kDiskSquare,
                                            options(104, 32, 32));
  EXPECT_GT(r.p_value, kAlpha) << r.report;
}

TEST(UniformTriangle, PdfIntegratesToOne) { EXPECT_NEAR(test::integrate_rect(triangle_pdf, kUnitSquare), 1, 1e-3); }

TEST(UniformTriangle, SamplesAreBarycentrics) {
  EXPECT_TRUE(
      maps_into_domain(square_to_uniform_triangle, [](Vec2 b) { return b.x >= 0 && b.y >= 0 && b.x + b.y <= 1; }));
}

TEST(UniformTriangle, SamplesFollowPdf) {
  const Chi2Result r =
      test::chi2_test_rect(point_sampler(square_to_uniform_triangle), triangle_pdf, kUnitSquare, options(105, 32, 32));
  EXPECT_GT(r.p_value, kAlpha) << r.report;
}

double wide_cone_pdf(const Vec3& w) { return w.z >= 0.5f ? uniform_cone_pdf(0.5f) : 0; }

TEST(UniformCone, WidePdfIntegratesToOne) { EXPECT_NEAR(test::integrate_sphere(wide_cone_pdf), 1, 1e-3); }

TEST(UniformCone, WideSamplesLieInCone) {
  EXPECT_TRUE(maps_into_domain([](Vec2 u) { return square_to_uniform_cone(u, 0.5f); },
                               [](Vec3 w) { return is_unit(w) && w.z >= 0.5f; }));
}

TEST(UniformCone, WideSamplesFollowPdf) {
  // 40 cos(theta) bins put a bin edge exactly on the cone's rim.
  const Chi2Result r = test::chi2_test_sphere(direction_sampler([](Vec2 u) { return square_to_uniform_cone(u, 0.5f); }),
                                              wide_cone_pdf, options(106, 40, 80));
  EXPECT_GT(r.p_value, kAlpha) << r.report;
}

// A cone of 1e-6 sr vanishes between the bins of any global grid, so the tiny
// cone is tested in local coordinates (s, phi) in [0,1] x [0,2pi], with
// s = sin^2(theta) / sin^2(theta_max). Since d(sin^2 theta) = 2 sin cos dtheta,
// solid angle is sin^2(theta_max) ds dphi / (2 cos theta) there.
double tiny_cone_sin2_max() {
  const double c = kTinyConeCos;
  return (1 - c) * (1 + c);
}

double tiny_cone_local_pdf(const Vec2& p) {
  const double sin2_max = tiny_cone_sin2_max();
  const double cos_theta = std::sqrt(1 - p.x * sin2_max);
  return uniform_cone_pdf(kTinyConeCos) * sin2_max / (2 * cos_theta);
}

const Rect kTinyConeLocal{0, 1, 0, kTwoPi};

TEST(UniformCone, TinyPdfIsAccurate) {
  const double exact = 1 / (kTwoPi * (1 - static_cast<double>(kTinyConeCos)));
  EXPECT_NEAR(uniform_cone_pdf(kTinyConeCos) / exact, 1, 1e-6);
  EXPECT_NEAR(test::integrate_rect(tiny_cone_local_pdf, kTinyConeLocal), 1, 1e-3);
}

TEST(UniformCone, TinySamplesLieInCone) {
  const double versine_max = 1 - static_cast<double>(kTinyConeCos);
  EXPECT_TRUE(maps_into_domain([](Vec2 u) { return square_to_uniform_cone(u, kTinyConeCos); },
                               [&](Vec3 w) {
                                 return std::abs(length(w) - 1) < 1e-6f && w.z >= kTinyConeCos &&
                                        versine(w) <= versine_max * (1 + 1e-5);
                               }));
}

// Recovering u from the sample checks that the map is the intended bijection;
// a cosine-based construction loses most digits of theta in a tiny cone.
void expect_inverse_consistent(float cos_theta_max) {
  const double versine_max = 1 - static_cast<double>(cos_theta_max);
  for (Vec2 u : square_points()) {
    const Vec3 w = square_to_uniform_cone(u, cos_theta_max);
    ASSERT_NEAR(versine(w) / versine_max, u.x, 1e-5) << "u = " << str(u) << ", w = " << str(w);
    if (u.x == 0) continue;  // phi is undefined at the pole
    double phi = std::atan2(static_cast<double>(w.y), static_cast<double>(w.x)) / kTwoPi;
    if (phi < 0) phi += 1;
    const double gap = std::abs(phi - u.y);
    ASSERT_LT(std::min(gap, 1 - gap), 1e-5) << "u = " << str(u) << ", w = " << str(w);
  }
}

TEST(UniformCone, WideIsInverseConsistent) { expect_inverse_consistent(0.5f); }
TEST(UniformCone, TinyIsInverseConsistent) { expect_inverse_consistent(kTinyConeCos); }

TEST(UniformCone, TinySamplesFollowPdf) {
  const double sin2_max = tiny_cone_sin2_max();
  const test::PointSampler local = [sin2_max](UniformSource& s) -> std::optional<Vec2> {
    const Vec3 w = square_to_uniform_cone(s.next_2d(), kTinyConeCos);
    const double x = w.x, y = w.y;
    double phi = std::atan2(y, x);
    if (phi < 0) phi += kTwoPi;
    // Rounding may put a sample on the rim a few ulps outside it.
    const double s_local = std::min((x * x + y * y) / sin2_max, 1.0);
    return Vec2(static_cast<float>(s_local), static_cast<float>(phi));
  };
  const Chi2Result r = test::chi2_test_rect(local, tiny_cone_local_pdf, kTinyConeLocal, options(107, 32, 32));
  EXPECT_GT(r.p_value, kAlpha) << r.report;
}

TEST(UniformCone, VersineFormHandlesConesBelowFloatCosineResolution) {
  // 1 - 1e-10 rounds to 1 in float, yet the versine form still samples it.
  constexpr float kVersine = 1e-10f;
  EXPECT_NEAR(uniform_cone_pdf_from_versine(kVersine) * kTwoPi * kVersine, 1, 1e-6);
  EXPECT_TRUE(maps_into_domain([](Vec2 u) { return square_to_uniform_cone_from_versine(u, kVersine); },
                               [](Vec3 w) { return is_unit(w) && versine(w) <= kVersine * (1 + 1e-5); }));
  const Vec3 rim = square_to_uniform_cone_from_versine({kOneMinusEpsilon, 0}, kVersine);
  EXPECT_NEAR(versine(rim) / kVersine, 1, 1e-5);
}

TEST(DiscreteDistribution, PmfIsNormalisedWeight) {
  const std::vector<float> weights = {1, 0, 3, 0, 4, 0};
  const DiscreteDistribution d(weights);
  ASSERT_EQ(d.size(), 6);
  EXPECT_FLOAT_EQ(d.sum(), 8);
  for (int i = 0; i < d.size(); ++i) EXPECT_FLOAT_EQ(d.pmf(i), weights[i] / 8) << "entry " << i;
}

TEST(DiscreteDistribution, NeverSamplesZeroWeights) {
  const std::vector<float> weights = {0, 0, 2, 0, 1, 0, 0, 5, 0};
  const DiscreteDistribution d(weights);
  // Exact CDF boundaries and their neighbours are where a zero-width interval
  // could be hit; out-of-range u must still land on a positive weight.
  std::vector<float> us = {0, kOneMinusEpsilon, 1, -0.25f, 1.5f};
  for (float boundary : {0.25f, 0.375f}) {
    us.push_back(boundary);
    us.push_back(std::nextafter(boundary, 0.0f));
    us.push_back(std::nextafter(boundary, 1.0f));
  }
  for (int i = 0; i < 10000; ++i) us.push_back(i / 10000.0f);
  for (float u : us) {
    float pmf = -1, u_remapped = -1;
    const int i = d.sample(u, &pmf, &u_remapped);
    ASSERT_GE(i, 0) << "u = " << u;
    ASSERT_LT(i, d.size()) << "u = " << u;
    EXPECT_GT(weights[i], 0) << "u = " << u << " selected entry " << i;
    EXPECT_EQ(pmf, d.pmf(i)) << "u = " << u;
    EXPECT_GE(u_remapped, 0) << "u = " << u;
    EXPECT_LT(u_remapped, 1) << "u = " << u;
  }
}

TEST(DiscreteDistribution, SingleEntryPassesUThrough) {
  const std::vector<float> weights = {3};
  const DiscreteDistribution d(weights);
  float pmf = 0, u_remapped = 0;
  EXPECT_EQ(d.sample(0.3f, &pmf, &u_remapped), 0);
  EXPECT_EQ(pmf, 1);
  EXPECT_FLOAT_EQ(u_remapped, 0.3f);
}

TEST(DiscreteDistribution, RejectsBadWeights) {
  constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<std::vector<float>> bad = {
      {}, {0, 0, 0}, {1, -1, 2}, {1, kNan}, {kInfinity, 1}, {-0.5f},
  };
  for (const std::vector<float>& weights : bad)
    EXPECT_THROW(DiscreteDistribution{weights}, std::invalid_argument) << "weights of size " << weights.size();
}

TEST(DiscreteDistribution, SamplesAndRemappedUFollowPmf) {
  // Joint histogram of (index, remapped u): the index must follow the weights
  // and the remapped u must be uniform and independent of it.
  constexpr int kEntries = 24, kRemapBins = 8, kSamples = 1'000'000;
  std::vector<float> weights(kEntries);
  UniformSource weight_source(11);
  for (int i = 0; i < kEntries; ++i) weights[i] = i % 5 == 3 ? 0 : weight_source.next_1d() * (i + 1);
  weights[1] = 1e-3f;  // a rare entry, pooled by the test
  const DiscreteDistribution d(weights);

  double total = 0;
  for (float w : weights) total += w;
  std::vector<double> observed(kEntries * kRemapBins, 0), expected(kEntries * kRemapBins);
  for (int i = 0; i < kEntries; ++i)
    for (int j = 0; j < kRemapBins; ++j) expected[i * kRemapBins + j] = kSamples * (weights[i] / total) / kRemapBins;

  UniformSource source(108);
  for (int n = 0; n < kSamples; ++n) {
    float u_remapped = 0;
    const int i = d.sample(source.next_1d(), nullptr, &u_remapped);
    observed[i * kRemapBins + static_cast<int>(u_remapped * kRemapBins)] += 1;
  }
  const Chi2Result r = test::chi2_test_counts(observed, expected);
  EXPECT_GT(r.p_value, kAlpha) << r.report;
}

TEST(Chi2Helper, PValueMatchesReferenceValues) {
  // Upper tail probabilities of the chi-square distribution, from mpmath.
  struct Case {
    double statistic;
    int dof;
    double p;
  };
  const Case cases[] = {
      {3.841458820694124, 1, 0.05},
      {18.307038053275146, 10, 0.05},
      {0.5, 3, 0.91889141165467585936},
      {2.0, 7, 0.95984036873010155712},
      {60.0, 30, 0.00092068239614866626},
      {1000.0, 1000, 0.49405285382923964195},
      {1200.0, 1000, 0.0000122559423306229042},
  };
  for (const Case& c : cases)
    EXPECT_NEAR(test::chi2_p_value(c.statistic, c.dof) / c.p, 1, 1e-9) << c.statistic << " with dof " << c.dof;
  EXPECT_EQ(test::chi2_p_value(0, 4), 1);
  EXPECT_EQ(test::chi2_p_value(kInfinity, 4), 0);
}

TEST(Chi2Helper, SidakAlpha) {
  EXPECT_NEAR(test::sidak_alpha(0.01, 1), 0.01, 1e-15);
  EXPECT_NEAR(test::sidak_alpha(0.05, 10), 0.005116196891823743, 1e-15);
}

// A test that cannot fail proves nothing: each wrong pairing must be rejected.
TEST(Chi2Helper, RejectsCosineSamplesAgainstUniformPdf) {
  Chi2Options o = options(201, 20, 40);
  o.sample_count = 100'000;
  const Chi2Result r = test::chi2_test_sphere(direction_sampler(square_to_cosine_hemisphere), hemisphere_pdf, o);
  EXPECT_LT(r.p_value, kAlpha) << r.report;
}

TEST(Chi2Helper, RejectsNaivePolarDisk) {
  // Uniform radius crowds the centre.
  const auto naive = [](Vec2 u) {
    const float phi = 2 * kPi * u.y;
    return Vec2(u.x * std::cos(phi), u.x * std::sin(phi));
  };
  Chi2Options o = options(202, 16, 16);
  o.sample_count = 100'000;
  const Chi2Result r = test::chi2_test_rect(point_sampler(naive), disk_pdf, kDiskSquare, o);
  EXPECT_LT(r.p_value, kAlpha) << r.report;
}

TEST(Chi2Helper, RejectsSamplesWherePdfIsZero) {
  Chi2Options o = options(203, 20, 40);
  o.sample_count = 10'000;
  const Chi2Result r = test::chi2_test_sphere(direction_sampler(square_to_uniform_sphere), hemisphere_pdf, o);
  EXPECT_EQ(r.p_value, 0) << r.report;
}

TEST(Chi2Helper, RejectsNonFinitePdf) {
  Chi2Options o = options(205, 20, 40);
  o.sample_count = 10'000;
  const Chi2Result r = test::chi2_test_sphere(
      direction_sampler(square_to_uniform_sphere),
      [](const Vec3& w) { return w.z < -0.5f ? std::numeric_limits<double>::quiet_NaN() : uniform_sphere_pdf(); }, o);
  EXPECT_EQ(r.p_value, 0) << r.report;
}

TEST(Chi2Helper, RejectsUnnormalisedPdf) {
  // The missing 10% of mass predicts failed samples that never come.
  Chi2Options o = options(204, 20, 40);
  o.sample_count = 100'000;
  const Chi2Result r = test::chi2_test_sphere(
      direction_sampler(square_to_uniform_sphere), [](const Vec3&) { return 0.9 * uniform_sphere_pdf(); }, o);
  EXPECT_LT(r.p_value, kAlpha) << r.report;
}

TEST(Chi2Helper, AcceptsFailuresAccountedForByPdf) {
  // A sampler that fails 30% of the time, with a pdf carrying 70% of the mass.
  const test::DirectionSampler sometimes = [](UniformSource& s) -> std::optional<Vec3> {
    if (s.next_1d() < 0.3f) return std::nullopt;
    return square_to_uniform_sphere(s.next_2d());
  };
  const Chi2Result r = test::chi2_test_sphere(
      sometimes, [](const Vec3&) { return 0.7 * uniform_sphere_pdf(); }, options(109, 20, 40));
  EXPECT_GT(r.p_value, kAlpha) << r.report;
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
