#include "core/color/glare_two_scale.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "core/color/glare_psf.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// The bilinear weights keep a pixel's light and its position: between
// the outer centres the weighted centres land on the pixel, beyond them
// the pixel goes wholly to the outer one. (At the spread's own scale, a
// light moved within its block changes the far glare by less than the
// transforms' rounding, so the test below cannot see it.)
TEST(GlareTwoScale, BlockWeightsKeepThePixelsPosition) {
  const int f = kGlareBlock, blocks = 13, width = f * blocks - 3;
  for (int i = 0; i < width; ++i) {
    const BlockNeighbours n = block_neighbours(i, blocks);
    const auto centre = [&](int b) { return f * b + (f - 1) / 2.0; };
    ASSERT_GE(n.t, 0) << i;
    ASSERT_LE(n.t, 1) << i;
    if (i < centre(0)) {
      EXPECT_EQ(n.lo, 0) << i;
      EXPECT_EQ(n.t, 0) << i;
    } else if (i > centre(blocks - 1)) {
      EXPECT_EQ(n.lo, blocks - 1) << i;
      EXPECT_EQ(n.hi, blocks - 1) << i;
    } else {
      EXPECT_EQ(n.hi, std::min(n.lo + 1, blocks - 1)) << i;
      EXPECT_NEAR((1 - n.t) * centre(n.lo) + n.t * centre(n.hi), i, 1e-5) << i;
    }
  }
}

// One bright pixel at a time, spread in two scales, against the exact
// kernel's values in double precision (glare_kernel, itself checked
// against the published PSF in glare_test.cpp). The sources sit at the
// centre, off a block centre, on an edge and in a corner, where the blocks
// run past the image. Within 0.1 % of the kernel wherever it is above
// 5e-8 (the transforms' single-precision rounding, about 3e-8 of the
// light in the exact convolution too), and the light that stays in the
// image within 0.1 % of the kernel's too (the far part's weights are the
// kernel sampled at the block centres' offsets, whose sum differs from the
// kernel's by about 2e-4).
TEST(GlareTwoScale, ReproducesTheKernelFromAnyPixel) {
  const int width = 640, height = 560;
  for (double d : {0.01, 0.1}) {
    const EvenKernel kernel = glare_kernel(width, height, d);
    for (auto [sx, sy] : {std::array<int, 2>{320, 280}, {323, 283}, {639, 3}, {0, 559}, {100, 4}}) {
      std::vector<float> image(size_t(width) * height * 3, 0.0f);
      for (int c = 0; c < 3; ++c) image[(size_t(sy) * width + sx) * 3 + c] = float(c + 1);
      spread_two_scale(image, width, height, d);
      double worst = 0, sum = 0, want_sum = 0;
      for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
          const double want = kernel.at(x - sx, y - sy);
          for (int c = 0; c < 3; ++c) {
            const double got = image[(size_t(y) * width + x) * 3 + c] / (c + 1);
            worst = std::max(worst, std::abs(got - want) / (1e-3 * want + 5e-8));
            sum += got;
          }
          want_sum += 3 * want;
        }
      EXPECT_LT(worst, 1) << "degrees per pixel " << d << ", light at " << sx << ", " << sy;
      EXPECT_NEAR(sum / want_sum, 1, 1e-3) << "degrees per pixel " << d << ", light at " << sx << ", " << sy;
    }
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
