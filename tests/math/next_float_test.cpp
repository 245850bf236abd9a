// The bit-stepping neighbours of a float agree with std::nextafter toward
// +-infinity everywhere: zeros of either sign, denormals, the largest
// finite floats, infinities, and floats spread over every exponent.

#include "core/math/next_float.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

TEST(NextFloat, AgreesWithNextafterTowardInfinities) {
  const float inf = std::numeric_limits<float>::infinity();
  std::vector<float> values = {0.0f,
                               -0.0f,
                               std::numeric_limits<float>::denorm_min(),
                               -std::numeric_limits<float>::denorm_min(),
                               std::numeric_limits<float>::min(),
                               -std::numeric_limits<float>::min(),
                               std::numeric_limits<float>::max(),
                               -std::numeric_limits<float>::max(),
                               inf,
                               -inf,
                               1.0f,
                               -1.0f};
  std::mt19937 rng(7);
  for (int i = 0; i < 100000; ++i) {
    const float v = std::bit_cast<float>(uint32_t(rng()));
    if (!std::isnan(v)) values.push_back(v);
  }
  for (const float v : values) {
    EXPECT_EQ(std::bit_cast<uint32_t>(next_float_up(v)), std::bit_cast<uint32_t>(std::nextafter(v, inf))) << v;
    EXPECT_EQ(std::bit_cast<uint32_t>(next_float_down(v)), std::bit_cast<uint32_t>(std::nextafter(v, -inf))) << v;
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
