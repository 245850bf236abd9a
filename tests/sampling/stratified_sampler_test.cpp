// The stratified sampler: every block of n = k^2 consecutive samples of a
// pixel (sample_count rounded up to a square) puts one value in each of the
// n strata of every 1-D dimension and one point in each cell of the k x k
// grid of every 2-D pair, in every stream and at any block; without jitter
// the values sit at the strata's centres. What every sampler promises is
// checked in sampler_test.cpp.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/sampling/sampler.h"
#include "tests/support/samplers.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

TEST(StratifiedSampler, EveryBlockStratifiesEveryDimension) {
  for (const auto& [count, side] : {std::pair{16, 4}, std::pair{10, 4}, std::pair{9, 3}, std::pair{1, 1}}) {
    auto s = test::make_sampler("stratified", {{"sample_count", int64_t(count)}});
    const int n = side * side;
    for (const SampleKey key : {SampleKey::camera({2, 7}), SampleKey::light_path({2, 7}), SampleKey::photon_round(5)})
      for (const uint64_t first : {uint64_t(0), uint64_t(3 * n)}) {
        std::vector<std::vector<int>> strata(3, std::vector<int>(n, 0)), cells(3, std::vector<int>(n, 0));
        for (uint64_t i = first; i < first + n; ++i) {
          s->start_sample(key, i, 4);
          for (int d = 0; d < 3; ++d) {
            ++strata[d][int(s->next_1d() * float(n))];
            const Vec2 u = s->next_2d();
            ++cells[d][int(u.y * float(side)) * side + int(u.x * float(side))];
          }
        }
        for (int d = 0; d < 3; ++d)
          for (int c = 0; c < n; ++c) {
            ASSERT_EQ(strata[d][c], 1) << "count " << count << ", 1-D dimension " << d << ", stratum " << c;
            ASSERT_EQ(cells[d][c], 1) << "count " << count << ", pair " << d << ", cell " << c;
          }
      }
  }
}

TEST(StratifiedSampler, WithoutJitterSamplesSitAtTheStrataCentres) {
  auto s = test::make_sampler("stratified", {{"sample_count", int64_t(16)}, {"jitter", false}});
  for (uint64_t i = 0; i < 16; ++i) {
    s->start_sample(SampleKey::camera({1, 1}), i, 0);
    const float a = s->next_1d() * 16 - 0.5f;
    EXPECT_EQ(a, std::floor(a));
    const Vec2 u = s->next_2d();
    EXPECT_EQ(u.x * 4 - 0.5f, std::floor(u.x * 4 - 0.5f));
    EXPECT_EQ(u.y * 4 - 0.5f, std::floor(u.y * 4 - 0.5f));
  }
}

TEST(StratifiedSampler, BadSampleCount) {
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><sensor type='perspective'><sampler type='stratified'>\n"
                               "<integer name='sample_count' value='0'/></sampler></sensor></scene>"),
              testing::HasSubstr("test.xml:2: parameter 'sample_count' of sampler 'stratified': must be between 1 "
                                 "and 2^30"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
