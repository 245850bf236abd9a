// The times of photon passes: one render's first 2^k passes meet each of
// 2^k equal parts of the shutter once (so motion resolves evenly as passes
// add up), and across seeds the time of any one pass is uniform over the
// shutter (so renders with other seeds are independent estimates of the
// shutter's average), by chi-square tests at 1 % over the four passes
// tried (Bonferroni).

#include "core/render/pass_time.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tests/support/chi2.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

TEST(PassTime, PassesFillTheShutterEvenly) {
  for (const uint64_t seed : {0ull, 7ull, 123456789ull})
    for (int k = 0; k <= 10; ++k) {
      const int parts = 1 << k;
      std::vector<int> hits(size_t(parts), 0);
      const float first = pass_time(0, seed);
      for (int pass = 0; pass < parts; ++pass) {
        const float t = pass_time(uint64_t(pass), seed);
        ASSERT_GE(t, 0.0f);
        ASSERT_LT(t, 1.0f);
        // Shifted back by the first pass's time, each lands on its own
        // multiple of 1 / 2^k.
        double u = double(t) - double(first);
        if (u < 0) u += 1;
        const double scaled = u * parts;
        ASSERT_NEAR(scaled, std::round(scaled), 1e-3) << "seed " << seed << ", pass " << pass;
        ++hits[size_t(std::llround(scaled)) % size_t(parts)];
      }
      for (int part = 0; part < parts; ++part) EXPECT_EQ(hits[size_t(part)], 1) << "seed " << seed << ", k " << k;
    }
}

TEST(PassTime, AcrossSeedsAPassTimeIsUniform) {
  constexpr int kBins = 32, kSeeds = 32000;
  for (const uint64_t pass : {0ull, 1ull, 5ull, 1000ull}) {
    std::vector<double> observed(kBins, 0), expected(kBins, double(kSeeds) / kBins);
    for (uint64_t seed = 0; seed < kSeeds; ++seed) observed[size_t(pass_time(pass, seed) * kBins)] += 1;
    double statistic = 0;
    for (int b = 0; b < kBins; ++b)
      statistic += (observed[b] - expected[b]) * (observed[b] - expected[b]) / expected[b];
    EXPECT_GT(test::chi2_p_value(statistic, kBins - 1), 0.01 / 4) << "pass " << pass;
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
