// GuidingPayoff on synthetic passes whose per-pixel means and noise are
// known: its relative variances against sigma^2 / (mu^2 + 0.01) averaged in
// the test, its costs, its verdict and what it ignores. Normal noise with a
// fixed seed; sigma is small beside mu, so that weighing by a mean of six
// samples instead of mu biases the figures by under 0.1%, and the
// tolerances (3% and 5%) are over five standard deviations of the
// estimates over 3 x 128 x 128 values.

#include "integrators/path/guiding/guiding_payoff.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <thread>

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

constexpr int kSide = 128;

double mu(int x, int y, int c) { return 0.5 + 0.5 * double((x * 7 + y * 13 + c * 29) % 101) / 100; }

// Feeds pass 0 (one sample, noise sigma0, 3 vertices each) and passes 1 ..
// `last` (noise sigma, 4 vertices of which 2 guided: a cost of 5), each
// pixel's samples in order.
GuidingPayoff::Verdict judged(double sigma0, double sigma, uint32_t last, uint64_t seed = 7) {
  GuidingPayoff payoff(kSide, kSide);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  for (uint32_t pass = 0; pass <= last; ++pass) {
    payoff.begin_pass(pass);
    const double s = pass == 0 ? sigma0 : sigma;
    for (int y = 0; y < kSide; ++y)
      for (int x = 0; x < kSide; ++x)
        for (uint32_t i = 0; i < (1u << pass); ++i) {
          float L[3];
          for (int c = 0; c < 3; ++c) L[c] = float(mu(x, y, c) + s * normal(rng));
          payoff.add({x, y}, Color(L[0], L[1], L[2]), pass == 0 ? WalkCost{3, 0} : WalkCost{4, 2});
        }
  }
  return payoff.judge();
}

double relative_variance(double sigma) {
  double sum = 0;
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x)
      for (int c = 0; c < 3; ++c) sum += sigma * sigma / (mu(x, y, c) * mu(x, y, c) + 0.01);
  return sum / (3.0 * kSide * kSide);
}

TEST(GuidingPayoff, ReadsEachPassesRelativeVarianceAndVertices) {
  for (uint32_t last : {2u, 4u}) {
    const auto v = judged(0.06, 0.02, last);
    EXPECT_NEAR(v.guided_variance, relative_variance(0.02), 0.03 * relative_variance(0.02)) << last;
    EXPECT_NEAR(v.unguided_variance, relative_variance(0.06), 0.05 * relative_variance(0.06)) << last;
    EXPECT_EQ(v.unguided_cost, 3);
    EXPECT_EQ(v.guided_cost, 5);
  }
  // Where the guided passes are the noisier, the mean pass 0 is read
  // against carries a variance (sigma^2 / 30 after pass 4, 30% of pass 0's)
  // that must come off.
  const auto v = judged(0.02, 0.06, 4);
  EXPECT_NEAR(v.unguided_variance, relative_variance(0.02), 0.05 * relative_variance(0.02));
  EXPECT_NEAR(v.guided_variance, relative_variance(0.06), 0.03 * relative_variance(0.06));
}

// Guided costs 5/3 as much per sample: it pays where it cuts the variance
// by more than that.
TEST(GuidingPayoff, PaysWhereItsVarianceFallsFurtherThanItsCostRises) {
  EXPECT_TRUE(judged(0.06, 0.02, 3).pays());    // variance / 9, cost x 5/3
  EXPECT_TRUE(judged(0.03, 0.02, 3).pays());    // / 2.25
  EXPECT_FALSE(judged(0.024, 0.02, 3).pays());  // / 1.44
  EXPECT_FALSE(judged(0.02, 0.04, 3).pays());
}

// Beyond 65536 pixels every stride-th along each axis is tracked: the
// rest may hold anything.
TEST(GuidingPayoff, ReadsEveryStrideThPixelOfALargeImage) {
  constexpr int kLarge = 3 * kSide;  // 147456 pixels: stride 2
  GuidingPayoff payoff(kLarge, kLarge);
  std::mt19937_64 rng(11);
  std::normal_distribution<double> normal;
  for (uint32_t pass = 0; pass <= 2; ++pass) {
    payoff.begin_pass(pass);
    const double s = pass == 0 ? 0.06 : 0.02;
    for (int y = 0; y < kLarge; ++y)
      for (int x = 0; x < kLarge; ++x)
        for (uint32_t i = 0; i < (1u << pass); ++i) {
          const bool tracked = x % 2 == 0 && y % 2 == 0;
          float L[3];
          for (int c = 0; c < 3; ++c) L[c] = tracked ? float(mu(x / 2, y / 2, c) + s * normal(rng)) : 1e6f;
          payoff.add({x, y}, Color(L[0], L[1], L[2]), {4, 0});
        }
  }
  const auto v = payoff.judge();
  // The tracked pixels are a 192 x 192 grid whose means repeat mu's.
  double expected = 0;
  for (int y = 0; y < kLarge / 2; ++y)
    for (int x = 0; x < kLarge / 2; ++x)
      for (int c = 0; c < 3; ++c) expected += 0.02 * 0.02 / (mu(x, y, c) * mu(x, y, c) + 0.01);
  expected /= 3.0 * (kLarge / 2) * (kLarge / 2);
  EXPECT_NEAR(v.guided_variance, expected, 0.03 * expected);
  EXPECT_EQ(v.guided_cost, 4);
}

// Pixels split between threads, in any interleaving: the same verdict, bit
// for bit, as one thread's.
TEST(GuidingPayoff, IsTheSameFromAnyThreads) {
  const auto fill = [](GuidingPayoff& payoff, int threads) {
    for (uint32_t pass = 0; pass <= 2; ++pass) {
      payoff.begin_pass(pass);
      std::vector<std::thread> workers;
      for (int t = 0; t < threads; ++t)
        workers.emplace_back([&, t] {
          for (int y = t; y < kSide; y += threads)
            for (int x = 0; x < kSide; ++x)
              for (uint32_t i = 0; i < (1u << pass); ++i) {
                std::mt19937_64 rng(uint64_t(y * kSide + x) * 64 + pass * 8 + i);
                const float v = float(std::generate_canonical<double, 53>(rng));
                payoff.add({x, y}, Color(v, 2 * v, 0.5f * v), {uint64_t(x % 5 + 1), uint64_t(x % 3)});
              }
        });
      for (auto& w : workers) w.join();
    }
  };
  GuidingPayoff one(kSide, kSide), four(kSide, kSide);
  fill(one, 1);
  fill(four, 4);
  const auto a = one.judge(), b = four.judge();
  EXPECT_EQ(a.guided_variance, b.guided_variance);
  EXPECT_EQ(a.unguided_variance, b.unguided_variance);
  EXPECT_EQ(a.guided_cost, b.guided_cost);
  EXPECT_EQ(a.unguided_cost, b.unguided_cost);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
