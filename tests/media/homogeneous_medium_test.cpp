// The homogeneous medium: Beer-Lambert transmittance, free-flight distances
// against exp(-sigma_t s) by chi-square, the chromatic estimator's
// unbiasedness per channel by z-tests against closed forms, the extremes of
// sigma_t, and bad parameters. Statistical tests use fixed seeds; each
// file's tests share a significance of 0.1% (Sidak-corrected).

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/chi2.h"
#include "tests/support/media.h"
#include "tests/support/samplers.h"
#include "tests/support/test_scenes.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using testing::HasSubstr;

// 1 chi-square test and 12 z-tests.
const double kAlpha = 1 - std::pow(1 - 0.001, 1.0 / 13);

std::shared_ptr<const Medium> homogeneous(const std::string& sigma_t, const std::string& albedo) {
  return test::make_medium("<medium type='homogeneous'><rgb name='sigma_t' value='" + sigma_t +
                           "'/><rgb name='albedo' value='" + albedo + "'/></medium>");
}

// Independent samples, one per index.
struct Samples {
  std::unique_ptr<Sampler> sampler = test::make_sampler("independent");
  Sampler& at(uint64_t i) {
    sampler->start_sample(SampleKey::camera({0, 0}), i, 7);
    return *sampler;
  }
};

TEST(HomogeneousMedium, TransmittanceIsBeerLambert) {
  const auto m = homogeneous("0.5, 1, 4", "0.5");
  Samples s;
  // A ray of length-2 direction to t = 0.75 crosses 1.5 units.
  const Color tr = m->transmittance({{0, 0, 0}, {0, 2, 0}}, 0.75f, s.at(0));
  EXPECT_NEAR(tr.r, std::exp(-0.75), 1e-6);
  EXPECT_NEAR(tr.g, std::exp(-1.5), 1e-6);
  EXPECT_NEAR(tr.b, std::exp(-6.0), 1e-7);
  const auto clear = homogeneous("0", "0.5");
  EXPECT_EQ(clear->transmittance({{0, 0, 0}, {1, 0, 0}}, kInfinity, s.at(0)), Color(1));
  const auto dense = homogeneous("1e6", "0.5");
  EXPECT_EQ(dense->transmittance({{0, 0, 0}, {1, 0, 0}}, 1, s.at(0)), Color(0));
}

TEST(HomogeneousMedium, FreeFlightDistancesFollowTheExponential) {
  const float sigma = 2, segment = 1;
  const auto m = homogeneous(std::to_string(sigma), "0.6");
  const int bins = 20, n = 200000;
  std::vector<double> observed(bins + 1, 0), expected(bins + 1, 0);
  Samples s;
  for (int i = 0; i < n; ++i) {
    // Direction of length 4: the segment's ray parameters are a quarter of its distances.
    const FreeFlight f = m->sample_free_flight({{0, 0, 0}, {0, 0, 4}}, segment / 4, Color(1), s.at(i));
    if (f.scattered) {
      // Transmittance cancels against the density: the albedo remains.
      ASSERT_NEAR(f.weight.r, 0.6f, 1e-6f);
      ASSERT_EQ(f.weight.r, f.weight.b);
      ++observed[std::min(bins - 1, int(f.t * 4 / segment * bins))];
    } else {
      ASSERT_EQ(f.weight, Color(1));
      ++observed[bins];
    }
  }
  for (int b = 0; b < bins; ++b)
    expected[b] = n * (std::exp(-sigma * segment * b / bins) - std::exp(-sigma * segment * (b + 1) / bins));
  expected[bins] = n * std::exp(-sigma * segment);
  const auto chi2 = test::chi2_test_counts(observed, expected);
  EXPECT_GT(chi2.p_value, kAlpha) << chi2.report;
}

void check_chromatic_free_flight(Color beta);

TEST(HomogeneousMedium, ChromaticFreeFlightIsUnbiasedPerChannel) {
  // Channels draw the distance in turn (equally for a grey path, mostly
  // the first for a reddish one); each channel's weighted estimates of
  // passing the segment and of scattering in its first half must still
  // have the closed-form means exp(-sigma T) and albedo (1 - exp(-sigma T/2)).
  for (const Color beta : {Color(1), Color(1, 0.2f, 0.05f)}) check_chromatic_free_flight(beta);
}

TEST(HomogeneousMedium, ChromaticEventsNeverRaiseTheSumOfThePathsChannels) {
  // With channels sharing the sampling in proportion to the path's weight,
  // sum_c beta_c w_c <= sum_c beta_c at every event (sigma_s <= sigma_t).
  const auto m = homogeneous("0.5, 3, 40", "1, 0.9, 1");
  Samples s;
  const Color beta(0.02f, 1, 0.5f);
  for (int i = 0; i < 10000; ++i) {
    const FreeFlight f = m->sample_free_flight({{0, 0, 0}, {1, 0, 0}}, 2, beta, s.at(i));
    const Color after = beta * f.weight;
    ASSERT_LE(after.r + after.g + after.b, (beta.r + beta.g + beta.b) * (1 + 1e-5f)) << i;
  }
}

void check_chromatic_free_flight(Color beta) {
  const Color sigma(0.5f, 1, 4), albedo(0.9f, 0.5f, 0.2f);
  const auto m = homogeneous("0.5, 1, 4", "0.9, 0.5, 0.2");
  ASSERT_TRUE(m->is_chromatic());
  const double T = 1.2;
  const int n = 200000;
  double pass[3][2] = {}, half[3][2] = {};
  Samples s;
  for (int i = 0; i < n; ++i) {
    const FreeFlight f = m->sample_free_flight({{0, 0, 0}, {1, 0, 0}}, float(T), beta, s.at(i));
    for (int c = 0; c < 3; ++c) {
      const double p = f.scattered ? 0 : f.weight[c], h = f.scattered && f.t < T / 2 ? f.weight[c] : 0;
      pass[c][0] += p;
      pass[c][1] += p * p;
      half[c][0] += h;
      half[c][1] += h * h;
    }
  }
  const double z = test::two_sided_z_critical(kAlpha);
  for (int c = 0; c < 3; ++c) {
    const auto check = [&](const double(&sums)[2], double expected, const char* what) {
      const double mean = sums[0] / n, var = sums[1] / n - mean * mean;
      EXPECT_LT(std::abs(mean - expected), z * std::sqrt(var / n))
          << what << " channel " << c << ": " << mean << " expected " << expected << " (path weight " << beta.r << ", "
          << beta.g << ", " << beta.b << ")";
    };
    check(pass[c], std::exp(-sigma[c] * T), "passing");
    check(half[c], albedo[c] * (1 - std::exp(-sigma[c] * T / 2)), "scattering in the first half");
  }
}

TEST(HomogeneousMedium, ExtremeExtinctionsStayFinite) {
  Samples s;
  const auto clear = homogeneous("0", "0.5");
  for (int i = 0; i < 100; ++i) {
    const FreeFlight f = clear->sample_free_flight({{0, 0, 0}, {1, 0, 0}}, kInfinity, Color(1), s.at(i));
    EXPECT_FALSE(f.scattered);
    EXPECT_EQ(f.weight, Color(1));
  }
  const auto dense = homogeneous("1e6, 1e6, 1e5", "0.5");
  for (int i = 0; i < 100; ++i) {
    const FreeFlight f = dense->sample_free_flight({{0, 0, 0}, {1, 0, 0}}, 1, Color(1), s.at(i));
    EXPECT_TRUE(f.scattered);
    EXPECT_TRUE(f.weight.is_finite());
    EXPECT_LT(f.t, 1e-3f);
  }
}

TEST(HomogeneousMedium, AbsorptionAndScatteringAreAnAlternative) {
  const auto m = test::make_medium(
      "<medium type='homogeneous'><rgb name='sigma_a' value='1, 2, 3'/><rgb name='sigma_s' value='3, 2, 1'/>"
      "<float name='scale' value='0.5'/></medium>");
  Samples s;
  const Color tr = m->transmittance({{0, 0, 0}, {1, 0, 0}}, 1, s.at(0));
  EXPECT_NEAR(tr.r, std::exp(-2.0), 1e-6);
  EXPECT_NEAR(tr.b, std::exp(-2.0), 1e-6);
  EXPECT_FALSE(m->is_chromatic());
}

TEST(HomogeneousMedium, BadParametersAreErrors) {
  const auto error = [](const std::string& params) {
    return test::load_error(
        "<scene version='3.0.0'>\n<medium type='homogeneous' id='m'>\n" + params + "\n</medium></scene>", "bad.xml");
  };
  EXPECT_THAT(error("<rgb name='albedo' value='1.5, 0.5, 0.5'/>"),
              HasSubstr("bad.xml:3: parameter 'albedo' of medium 'homogeneous': must lie in [0, 1] in every channel"));
  EXPECT_THAT(error("<float name='sigma_t' value='-1'/>"),
              HasSubstr("bad.xml:3: parameter 'sigma_t' of medium 'homogeneous': must be finite and at least 0"));
  EXPECT_THAT(error("<float name='sigma_t' value='1'/><float name='sigma_a' value='1'/>"),
              HasSubstr("bad.xml:3: parameter 'sigma_t' of medium 'homogeneous': give either sigma_t and albedo or "
                        "sigma_a and sigma_s, not both"));
  EXPECT_THAT(error("<float name='scale' value='1e38'/><float name='sigma_t' value='100'/>"),
              HasSubstr("overflow single precision"));
  EXPECT_THAT(error("<float name='sigma' value='1'/>"), HasSubstr("bad.xml:3"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
