// A smooth gradient quantised to 8 bits: plain rounding turns it into wide
// bands of one value; the dither must break those up while keeping every
// region's average on the true value (a histogram of the output per region).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/image/image_output.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

constexpr int kWidth = 2048, kHeight = 16;

// From 10/255 to 14/255 across the image: four quantisation steps.
std::vector<float> ramp() {
  std::vector<float> rgb(size_t(kWidth) * kHeight * 3);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x)
      for (int c = 0; c < 3; ++c) rgb[(size_t(y) * kWidth + x) * 3 + c] = (10 + 4.0f * x / kWidth) / 255;
  return rgb;
}

int longest_run(const std::vector<uint16_t>& q, int row, int channel) {
  int longest = 1, run = 1;
  for (int x = 1; x < kWidth; ++x) {
    const size_t i = (size_t(row) * kWidth + x) * 3 + channel;
    run = q[i] == q[i - 3] ? run + 1 : 1;
    longest = std::max(longest, run);
  }
  return longest;
}

TEST(Dither, BreaksBandsAndKeepsRegionAverages) {
  const auto values = ramp();
  const auto dithered = quantize(values, kWidth, 8);
  // Undithered, each of the four steps is a band about kWidth / 4 wide.
  std::vector<uint16_t> rounded(values.size());
  for (size_t i = 0; i < values.size(); ++i) rounded[i] = uint16_t(std::lround(values[i] * 255));
  EXPECT_GE(longest_run(rounded, 0, 0), kWidth / 4 - 1);
  for (int row = 0; row < kHeight; ++row)
    for (int c = 0; c < 3; ++c) EXPECT_LT(longest_run(dithered, row, c), 32) << "row " << row;

  // Triangular dither of +-1 step is unbiased: each block of 64 columns
  // averages to the ramp's mean there, within 0.1 step (the block's
  // standard error is about 0.02 step).
  for (int x0 = 0; x0 < kWidth; x0 += 64) {
    double sum = 0, truth = 0;
    int n = 0;
    for (int y = 0; y < kHeight; ++y)
      for (int x = x0; x < x0 + 64; ++x)
        for (int c = 0; c < 3; ++c) {
          const size_t i = (size_t(y) * kWidth + x) * 3 + c;
          sum += dithered[i];
          truth += values[i] * 255.0;
          ++n;
        }
    EXPECT_NEAR(sum / n, truth / n, 0.1) << "columns from " << x0;
  }
  // Noise below one step plus rounding: always less than 1.5 steps off.
  for (size_t i = 0; i < values.size(); ++i) EXPECT_LT(std::abs(dithered[i] - values[i] * 255), 1.5f);
}

TEST(Dither, SixteenBitsRoundWithoutNoise) {
  const auto q = quantize(std::vector<float>{0.0f, 0.5f, 1.0f, 2.0f, -1.0f, NAN}, 2, 16);
  EXPECT_EQ(q, (std::vector<uint16_t>{0, 32768, 65535, 65535, 0, 0}));
}

TEST(Dither, IsReproducible) { EXPECT_EQ(quantize(ramp(), kWidth, 8), quantize(ramp(), kWidth, 8)); }

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
