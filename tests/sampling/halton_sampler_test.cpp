// The halton sampler: the first sample_count samples of a pixel put, in
// dimension d with the d-th prime base b, floor or ceil of count / b^k
// values in each interval of width b^-k (b^k <= count); and in the pairs
// of bases (2, 3) and (5, 7), floor or ceil of count / (p^i q^j) points in
// each box of p^-i x q^-j (p^i q^j <= count), in every stream. Past the
// 1024th prime the bases repeat with scrambles of their own. What every
// sampler promises is checked in sampler_test.cpp.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <vector>

#include "tests/support/samplers.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// How often each box of a grid of columns x rows is hit by `points`
// must be floor or ceil of their number over the boxes.
void expect_even(const std::vector<Vec2>& points, int columns, int rows, const std::string& what) {
  std::vector<int> hits(size_t(columns * rows), 0);
  for (const Vec2& u : points) ++hits[size_t(int(u.y * float(rows)) * columns + int(u.x * float(columns)))];
  const int boxes = columns * rows, n = int(points.size());
  for (int c = 0; c < boxes; ++c)
    ASSERT_TRUE(hits[c] == n / boxes || hits[c] == (n + boxes - 1) / boxes)
        << what << ": " << columns << " x " << rows << " box " << c << " holds " << hits[c] << " of " << n;
}

TEST(HaltonSampler, FirstSamplesAreStratifiedInEveryBaseAndPair) {
  const int primes[] = {2, 3, 5, 7, 11, 13};
  for (const int count : {72, 35, 50, 1})
    for (const SampleKey key : {SampleKey::camera({2, 7}), SampleKey::light_path({2, 7}), SampleKey::photon_round(5)}) {
      auto s = test::make_sampler("halton", {{"sample_count", int64_t(count)}, {"seed", int64_t(9)}});
      std::vector<std::vector<Vec2>> single(6), pairs(2);
      for (int i = 0; i < count; ++i) {
        s->start_sample(key, uint64_t(i), 4);
        for (int d = 0; d < 6; ++d) single[d].push_back({s->next_1d(), 0.5f});
        s->start_sample(key, uint64_t(i), 4);
        for (int p = 0; p < 2; ++p) pairs[p].push_back(s->next_2d());
      }
      for (int d = 0; d < 6; ++d)
        for (int width = primes[d]; width <= count; width *= primes[d])
          expect_even(single[d], width, 1, "count " + std::to_string(count) + ", base " + std::to_string(primes[d]));
      for (int p = 0; p < 2; ++p)
        for (int columns = 1; columns <= count; columns *= primes[2 * p])
          for (int rows = 1; columns * rows <= count; rows *= primes[2 * p + 1])
            expect_even(pairs[p], columns, rows, "count " + std::to_string(count) + ", pair " + std::to_string(p));
    }
}

TEST(HaltonSampler, BasesRepeatPastTheTableWithScramblesOfTheirOwn) {
  auto s = test::make_sampler("halton", {{"sample_count", int64_t(16)}});
  std::vector<Vec2> first, repeated;
  int equal = 0;
  for (uint64_t i = 0; i < 16; ++i) {
    s->start_sample(SampleKey::camera({3, 4}), i, 1);
    first.push_back({s->next_1d(), 0.5f});
    for (int d = 1; d < 1024; ++d) s->next_1d();
    repeated.push_back({s->next_1d(), 0.5f});
    equal += first.back().x == repeated.back().x;
  }
  for (const int width : {2, 4, 8, 16}) expect_even(repeated, width, 1, "dimension 1024");
  EXPECT_EQ(equal, 0);
}

TEST(HaltonSampler, BadSampleCount) {
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><sensor type='perspective'><sampler type='halton'>\n"
                               "<integer name='sample_count' value='0'/></sampler></sensor></scene>"),
              testing::HasSubstr("test.xml:2: parameter 'sample_count' of sampler 'halton': must be a positive "
                                 "32-bit count"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
