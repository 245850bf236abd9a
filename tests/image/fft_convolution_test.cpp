#include "core/image/fft_convolution.h"

#include <gtest/gtest.h>

#include <random>

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

TEST(FftLength, SmallestSevenSmoothLengthAtLeastN) {
  EXPECT_EQ(fft_length(1), 1);
  EXPECT_EQ(fft_length(11), 12);
  EXPECT_EQ(fft_length(13), 14);
  EXPECT_EQ(fft_length(97), 98);
  EXPECT_EQ(fft_length(1021), 1024);
  EXPECT_EQ(fft_length(7679), 7680);
}

// The transform's result against the convolution summed directly, over an
// odd-sized image and three channels, with a kernel larger than the image
// and one smaller.
void expect_direct_sum(int kernel_width, int kernel_height) {
  const int width = 13, height = 7, channels = 3;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  EvenKernel kernel{kernel_width, kernel_height, {}};
  for (int i = 0; i < kernel.width * kernel.height; ++i) kernel.quadrant.push_back(u(rng));
  std::vector<float> image(size_t(width) * height * channels);
  for (float& v : image) v = float(u(rng));

  std::vector<double> expected(image.size(), 0.0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int sy = 0; sy < height; ++sy)
        for (int sx = 0; sx < width; ++sx)
          for (int c = 0; c < channels; ++c) {
            const int dx = x - sx < 0 ? sx - x : x - sx, dy = y - sy < 0 ? sy - y : y - sy;
            if (dx >= kernel.width || dy >= kernel.height) continue;
            expected[(size_t(y) * width + x) * channels + c] +=
                kernel.quadrant[size_t(dy) * kernel.width + dx] * image[(size_t(sy) * width + sx) * channels + c];
          }
  convolve(image, width, height, channels, kernel);
  for (size_t i = 0; i < image.size(); ++i) EXPECT_NEAR(image[i], expected[i], 1e-4 * expected[i]) << i;
}

TEST(FftConvolution, MatchesTheDirectSum) {
  expect_direct_sum(15, 8);
  expect_direct_sum(4, 3);
}

TEST(EvenKernel, TotalCountsEveryMirrorImage) {
  // Quadrant 2 x 2 stands for a 3 x 3 kernel: 1 centre, 2 + 2 edges, 4 corners.
  const EvenKernel kernel{2, 2, {1, 10, 100, 1000}};
  EXPECT_DOUBLE_EQ(kernel.total(), 1 + 2 * 10 + 2 * 100 + 4 * 1000);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
