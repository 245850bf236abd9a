// The multijitter sampler: every block of n = a * b consecutive samples of
// a pixel (sample_count rounded up to a columns, a = ceil(sqrt(count)), and
// b rows) puts one point of every 2-D pair in each cell of the a x b grid
// and, along each axis, one in each of the n strata of width 1/n; every 1-D
// dimension puts one value in each of n strata; in every stream and at any
// block. Without jitter the values sit at the centres of the finest strata.
// What every sampler promises is checked in sampler_test.cpp.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tests/support/samplers.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

struct Grid {
  int count, columns, rows;
};

TEST(MultijitterSampler, EveryBlockIsMultiJitteredInEveryDimension) {
  for (const Grid g : {Grid{16, 4, 4}, Grid{10, 4, 3}, Grid{7, 3, 3}, Grid{12, 4, 3}, Grid{2, 2, 1}, Grid{1, 1, 1}}) {
    auto s = test::make_sampler("multijitter", {{"sample_count", int64_t(g.count)}});
    const int n = g.columns * g.rows;
    for (const SampleKey key : {SampleKey::camera({2, 7}), SampleKey::light_path({2, 7}), SampleKey::photon_round(5)})
      for (const uint64_t first : {uint64_t(0), uint64_t(3 * n)}) {
        std::vector<std::vector<int>> strata(3, std::vector<int>(n, 0)), cells(3, std::vector<int>(n, 0)),
            x_strata(3, std::vector<int>(n, 0)), y_strata(3, std::vector<int>(n, 0));
        for (uint64_t i = first; i < first + n; ++i) {
          s->start_sample(key, i, 4);
          for (int d = 0; d < 3; ++d) {
            ++strata[d][int(s->next_1d() * float(n))];
            const Vec2 u = s->next_2d();
            ++cells[d][int(u.y * float(g.rows)) * g.columns + int(u.x * float(g.columns))];
            ++x_strata[d][int(u.x * float(n))];
            ++y_strata[d][int(u.y * float(n))];
          }
        }
        for (int d = 0; d < 3; ++d)
          for (int c = 0; c < n; ++c) {
            ASSERT_EQ(strata[d][c], 1) << "count " << g.count << ", 1-D dimension " << d << ", stratum " << c;
            ASSERT_EQ(cells[d][c], 1) << "count " << g.count << ", pair " << d << ", cell " << c;
            ASSERT_EQ(x_strata[d][c], 1) << "count " << g.count << ", pair " << d << ", x stratum " << c;
            ASSERT_EQ(y_strata[d][c], 1) << "count " << g.count << ", pair " << d << ", y stratum " << c;
          }
      }
  }
}

TEST(MultijitterSampler, WithoutJitterSamplesSitAtTheFinestStrataCentres) {
  auto s = test::make_sampler("multijitter", {{"sample_count", int64_t(12)}, {"jitter", false}});
  for (uint64_t i = 0; i < 12; ++i) {
    s->start_sample(SampleKey::camera({1, 1}), i, 0);
    const float a = s->next_1d() * 12 - 0.5f;
    EXPECT_EQ(a, std::round(a));
    const Vec2 u = s->next_2d();
    EXPECT_NEAR(u.x * 12 - 0.5f, std::round(u.x * 12 - 0.5f), 1e-5f) << u.x;
    EXPECT_NEAR(u.y * 12 - 0.5f, std::round(u.y * 12 - 0.5f), 1e-5f) << u.y;
  }
}

TEST(MultijitterSampler, BadSampleCount) {
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><sensor type='perspective'><sampler type='multijitter'>\n"
                               "<integer name='sample_count' value='-3'/></sampler></sensor></scene>"),
              testing::HasSubstr("test.xml:2: parameter 'sample_count' of sampler 'multijitter': must be between 1 "
                                 "and 2^30"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
