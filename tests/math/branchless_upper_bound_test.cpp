#include "core/math/branchless_upper_bound.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// Against std::upper_bound on sorted arrays of every length up to 40, with
// runs of equal values (a CDF's zero-weight entries), probing each value,
// the gaps between them and both ends.
TEST(BranchlessUpperBound, AgreesWithTheStandardSearch) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> step(0, 2);
  for (size_t n = 0; n <= 40; ++n) {
    std::vector<float> values;
    float v = 0;
    for (size_t i = 0; i < n; ++i) values.push_back(v += float(step(rng)));
    std::vector<float> probes{-1, v + 1, std::numeric_limits<float>::quiet_NaN()};
    for (float x : values) probes.insert(probes.end(), {x, x - 0.5f, x + 0.5f});
    for (float x : probes)
      EXPECT_EQ(branchless_upper_bound(values, x),
                size_t(std::upper_bound(values.begin(), values.end(), x) - values.begin()))
          << "n = " << n << ", x = " << x;
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
