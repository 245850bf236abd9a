// The Russian-roulette policy of every walk, checked against its rule
// computed here: no number before rr_depth; from there one number per
// vertex, a survival probability of 1 at or above rr_threshold and
// min(t, rr_max_survival) below it (t the throughput's largest channel
// times eta_scale). Survival frequencies are binomial tests at
// significance 0.1 % each, with fixed seeds.

#include "core/transport/russian_roulette.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <tuple>

#include "tests/support/samplers.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// The next number `sampler` gives after `drawn` numbers of sample 0.
float number_after(int drawn) {
  auto sampler = test::make_sampler("independent");
  sampler->start_sample(SampleKey::camera({0, 0}), 0, 1);
  for (int i = 0; i < drawn; ++i) sampler->next_1d();
  return sampler->next_1d();
}

TEST(RussianRoulette, DrawsOneNumberFromRrDepthOnWhateverTheThroughput) {
  const RussianRoulette roulette{3, 0.95f, 0.1f};
  for (const float t : {0.05f, 0.5f, 2.0f}) {
    for (const int64_t segments : {1, 2, 3, 7}) {
      auto sampler = test::make_sampler("independent");
      sampler->start_sample(SampleKey::camera({0, 0}), 0, 1);
      float q = -1;
      roulette.survives(segments, Color(t), 1, *sampler, &q);
      EXPECT_EQ(sampler->next_1d(), number_after(segments >= 3 ? 1 : 0)) << t << " " << segments;
      if (segments < 3 || t >= 0.1f) {
        EXPECT_EQ(q, 1) << t << " " << segments;
      }
    }
  }
}

TEST(RussianRoulette, SurvivesAtOrAboveTheThresholdAndWithProbabilityTBelow) {
  const RussianRoulette roulette{1, 0.95f, 0.25f};
  auto sampler = test::make_sampler("independent");
  const double z = test::two_sided_z_critical(0.001);
  // t = max channel x eta_scale; above the threshold every walk goes on.
  for (const auto& [throughput, eta_scale, expected] :
       {std::tuple{Color(0.01f, 0.2f, 0.03f), 1.0f, 0.2}, std::tuple{Color(0.05f), 2.0f, 0.1},
        std::tuple{Color(0.3f), 1.0f, 1.0}, std::tuple{Color(0.2f), 1.25f, 1.0},
        std::tuple{Color(0.04f), 0.5f, 0.02}}) {
    const int n = 20000;
    int survived = 0;
    for (int i = 0; i < n; ++i) {
      sampler->start_sample(SampleKey::camera({i % 64, i / 64}), uint64_t(i), 5);
      float q = -1;
      survived += roulette.survives(4, throughput, eta_scale, *sampler, &q);
      ASSERT_FLOAT_EQ(q, float(expected));
    }
    if (expected == 1.0) {
      EXPECT_EQ(survived, n);
    } else {
      const double sd = std::sqrt(n * expected * (1 - expected));
      EXPECT_LT(std::abs(survived - n * expected), z * sd) << survived << " of " << n << ", expected " << expected;
    }
  }
}

// rr_max_survival still bounds q below the threshold, and an infinite
// threshold is Mitsuba's rule: roulette at any throughput.
TEST(RussianRoulette, MaxSurvivalBoundsQAndAnInfiniteThresholdRoulettesEverything) {
  auto sampler = test::make_sampler("independent");
  sampler->start_sample(SampleKey::camera({0, 0}), 0, 1);
  float q = -1;
  RussianRoulette{1, 0.5f, 0.9f}.survives(1, Color(0.8f), 1, *sampler, &q);
  EXPECT_EQ(q, 0.5f);
  RussianRoulette{1, 0.95f, std::numeric_limits<float>::infinity()}.survives(1, Color(3.0f), 1, *sampler, &q);
  EXPECT_EQ(q, 0.95f);
}

// A throughput that is not finite meets roulette whatever the threshold:
// NaN ends the walk, an infinite one survives with rr_max_survival, so no
// broken path walks for ever.
TEST(RussianRoulette, ThroughputsThatAreNotFiniteAlwaysMeetRoulette) {
  auto sampler = test::make_sampler("independent");
  const RussianRoulette roulette{1, 0.95f, 0.1f};
  for (int i = 0; i < 100; ++i) {
    sampler->start_sample(SampleKey::camera({i, 0}), 0, 1);
    float q = -1;
    EXPECT_FALSE(roulette.survives(3, Color(std::nanf("")), 1, *sampler, &q));
    roulette.survives(3, Color(std::numeric_limits<float>::infinity()), 1, *sampler, &q);
    EXPECT_EQ(q, 0.95f);
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
