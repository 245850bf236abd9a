// The hashed permutation the stratifying samplers share: a bijection on
// [0, n) for every seed, and, over seeds, each i sent to each image equally
// often (chi-square at 1 %, Sidak-corrected over the cases), for powers of
// two and others alike. Seeds are a fixed sequence of hashes. And the
// per-dimension hash, whose first keys are tabled.

#include "core/sampling/sample_hash.h"

#include <gtest/gtest.h>

#include <vector>

#include "tests/support/chi2.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

TEST(HashedPermutation, IsABijectionForEverySeed) {
  for (const uint32_t n : {1u, 2u, 3u, 5u, 7u, 16u, 36u, 100u, 1000u})
    for (uint64_t k = 0; k < 64; ++k) {
      std::vector<int> hits(n, 0);
      for (uint32_t i = 0; i < n; ++i) ++hits[hashed_permutation(i, n, mix_bits(k + 1))];
      for (uint32_t a = 0; a < n; ++a) ASSERT_EQ(hits[a], 1) << "n " << n << ", seed " << k << ", image " << a;
    }
}

TEST(HashedPermutation, SendsEachIndexToEachImageEquallyOftenOverSeeds) {
  const uint32_t sizes[] = {3, 5, 6, 7, 9, 12, 16, 100};
  constexpr int kSeeds = 1 << 16;
  const double alpha = test::sidak_alpha(0.01, 2 * int(std::size(sizes)));
  for (const uint32_t n : sizes)
    for (const uint32_t i : {0u, n - 1}) {
      std::vector<double> observed(n, 0.0), expected(n, double(kSeeds) / n);
      for (uint64_t k = 0; k < kSeeds; ++k)
        observed[hashed_permutation(i, n, mix_bits(k * 0x9e3779b97f4a7c15ULL + 7))] += 1;
      const test::Chi2Result r = test::chi2_test_counts(observed, expected);
      EXPECT_GT(r.p_value, alpha) << "n " << n << ", index " << i << ": " << r.report;
    }
}

// The tabled dimension keys are the hash they stand for, across the end
// of the table: the murmur finaliser is written out here again.
TEST(DimensionHash, EqualsTheHashOfTheDimensionAcrossTheTable) {
  const auto finalise = [](uint64_t v) {
    v = (v ^ (v >> 33)) * 0xff51afd7ed558ccdULL;
    v = (v ^ (v >> 33)) * 0xc4ceb9fe1a85ec53ULL;
    return v ^ (v >> 33);
  };
  for (const uint64_t sample : {uint64_t(0), uint64_t(0x243f6a8885a308d3ULL)})
    for (uint64_t d = 0; d < 300; ++d)
      ASSERT_EQ(dimension_hash(sample, d), finalise(sample ^ finalise(d * 0x9e3779b97f4a7c15ULL))) << "dimension " << d;
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
