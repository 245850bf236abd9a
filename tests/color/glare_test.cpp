#include "core/color/glare.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "core/color/glare_psf.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// Spencer et al.'s photopic PSF as the paper prints it, theta in degrees.
double paper_psf(double theta) {
  const double f0 = 2.61e6 * std::exp(-(theta / 0.02) * (theta / 0.02));
  const double f1 = 20.91 / std::pow(theta + 0.02, 3);
  const double f2 = 72.37 / std::pow(theta + 0.02, 2);
  return 0.384 * f0 + 0.478 * f1 + 0.138 * f2;
}

// The paper's PSF over the pixel at offset (dx, dy), pixels of d degrees,
// by the midpoint rule on m x m cells.
double pixel_integral(int dx, int dy, double d, int m) {
  double sum = 0;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i)
      sum += paper_psf(std::hypot((dx - 0.5 + (i + 0.5) / m) * d, (dy - 0.5 + (j + 0.5) / m) * d));
  return sum * (d / m) * (d / m);
}

// What the kernel should be, from the paper's formula alone: the pixel
// integrals over every offset of a width x height image, normalised to one.
std::vector<double> expected_kernel(int width, int height, double d) {
  std::vector<double> quadrant(size_t(width) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const int r = std::max(x, y);
      quadrant[size_t(y) * width + x] = pixel_integral(x, y, d, r <= 2 ? 256 : r <= 12 ? 16 : 2);
    }
  double total = 0;
  for (int y = 1 - height; y < height; ++y)
    for (int x = 1 - width; x < width; ++x) total += quadrant[size_t(std::abs(y)) * width + size_t(std::abs(x))];
  for (double& w : quadrant) w /= total;
  return quadrant;
}

TEST(GlarePsf, IsThePublishedFormula) {
  for (double theta : {0.0, 0.005, 0.02, 0.1, 1.0, 10.0, 60.0})
    EXPECT_NEAR(glare_psf(theta), paper_psf(theta), 1e-12 * paper_psf(theta)) << theta;
}

// The core and the first tail each integrate to one over a steradian
// (square degrees over (180/pi)^2); the second tail's 1/theta^2 gives
// 2 pi 72.37 (ln((R + a) / a) + a / (R + a) - 1) within R degrees.
TEST(GlarePsf, CoreAndFirstTailIntegrateToOneSteradian) {
  const double R = 30, a = 0.02, per_sr = std::pow(180 / std::numbers::pi, 2);
  const int n = 400000;
  double integral = 0;
  // theta = R t^4 puts the nodes where the PSF changes fast.
  for (int i = 0; i < n; ++i) {
    const double t = (i + 0.5) / n, theta = R * std::pow(t, 4), dtheta = 4 * R * std::pow(t, 3) / n;
    integral += glare_psf(theta) * 2 * std::numbers::pi * theta * dtheta;
  }
  const double f1_within_R =
      2 * std::numbers::pi * 20.91 * (1 / (2 * a) - 1 / (R + a) + a / (2 * (R + a) * (R + a))) / per_sr;
  const double f2_within_R = 2 * std::numbers::pi * 72.37 * (std::log((R + a) / a) + a / (R + a) - 1) / per_sr;
  EXPECT_NEAR(integral / per_sr, 0.384 + 0.478 * f1_within_R + 0.138 * f2_within_R, 2e-3);
  EXPECT_NEAR(f1_within_R, 1, 2e-3);
}

TEST(GlareKernel, SumsToOneOverEveryOffset) {
  const int width = 40, height = 30;
  const EvenKernel kernel = glare_kernel(width, height, 0.1);
  double sum = 0;
  for (int dy = 1 - height; dy < height; ++dy)
    for (int dx = 1 - width; dx < width; ++dx) sum += kernel.at(dx, dy);
  EXPECT_NEAR(sum, 1, 1e-9);
}

// One bright pixel in the middle of a black image becomes the kernel,
// which the paper's formula predicts pixel by pixel: in the core (where
// the Gaussian lives inside a pixel or two) and out in the tails.
TEST(Glare, OneBrightPixelReproducesThePsf) {
  for (double d : {0.005, 0.05, 0.5}) {
    const int width = 33, height = 25, cx = 16, cy = 12;
    std::vector<float> rgb(size_t(width) * height * 3, 0.0f);
    for (int c = 0; c < 3; ++c) rgb[(size_t(cy) * width + cx) * 3 + c] = 1000.0f * float(c + 1);
    ASSERT_TRUE(apply_glare(rgb, width, height, {GlareMode::Whole, d}));
    const std::vector<double> expected = expected_kernel(width, height, d);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x)
        for (int c = 0; c < 3; ++c) {
          const double want = 1000.0 * (c + 1) * expected[size_t(std::abs(y - cy)) * width + size_t(std::abs(x - cx))];
          EXPECT_NEAR(rgb[(size_t(y) * width + x) * 3 + c], want, 5e-3 * want + 1e-6)
              << "d " << d << " at " << x << "," << y;
        }
  }
}

// The same pixel moved moves its glare with it; the glare is mirror
// symmetric about the pixel. Within the float transforms' rounding, about
// 1e-7 of the source's light.
TEST(Glare, ShiftInvariantAndSymmetric) {
  const int width = 48, height = 36;
  const auto bright_at = [&](int x, int y) {
    std::vector<float> rgb(size_t(width) * height * 3, 0.0f);
    for (int c = 0; c < 3; ++c) rgb[(size_t(y) * width + x) * 3 + c] = 50;
    apply_glare(rgb, width, height, {GlareMode::Whole, 0.08});
    return rgb;
  };
  const auto a = bright_at(20, 15), b = bright_at(27, 19);
  const auto at = [&](const std::vector<float>& rgb, int x, int y) { return rgb[(size_t(y) * width + x) * 3 + 1]; };
  for (int y = 0; y + 4 < height; ++y)
    for (int x = 0; x + 7 < width; ++x) EXPECT_NEAR(at(b, x + 7, y + 4), at(a, x, y), 1e-5 * at(a, x, y) + 5e-6);
  for (int dy = 0; dy <= 14; ++dy)
    for (int dx = 0; dx <= 19; ++dx) {
      const float v = at(a, 20 + dx, 15 + dy);
      EXPECT_NEAR(at(a, 20 - dx, 15 + dy), v, 1e-5 * v + 5e-6);
      EXPECT_NEAR(at(a, 20 + dx, 15 - dy), v, 1e-5 * v + 5e-6);
    }
}

TEST(Glare, ClippedLeavesAnImageWithinTheDisplayRangeAsItIs) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> u(0, 1);
  std::vector<float> rgb(20 * 10 * 3);
  for (float& v : rgb) v = u(rng);
  rgb[7] = 1.0f;  // at the limit is within it
  const std::vector<float> before = rgb;
  EXPECT_FALSE(apply_glare(rgb, 20, 10, {GlareMode::Clipped, 0.1}));
  EXPECT_EQ(rgb, before);
  EXPECT_FALSE(apply_glare(rgb, 20, 10, {GlareMode::None, 0.1}));
  EXPECT_EQ(rgb, before);
}

// Clipped: a pixel beyond the range keeps its colour scaled so its largest
// channel is 1, and only the excess is spread, over every pixel alike.
TEST(Glare, ClippedSpreadsOnlyTheExcess) {
  const int width = 21, height = 15, cx = 10, cy = 7;
  const double d = 0.2;
  std::vector<float> rgb(size_t(width) * height * 3, 0.25f);
  const float bright[3] = {8, 4, 0.5f};
  for (int c = 0; c < 3; ++c) rgb[(size_t(cy) * width + cx) * 3 + c] = bright[c];
  ASSERT_TRUE(apply_glare(rgb, width, height, {GlareMode::Clipped, d}));
  const std::vector<double> kernel = expected_kernel(width, height, d);
  const double kept[3] = {1, 0.5, 0.0625};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c) {
        const bool source = x == cx && y == cy;
        const double spread =
            (bright[c] - kept[c]) * kernel[size_t(std::abs(y - cy)) * width + size_t(std::abs(x - cx))];
        const double want = (source ? kept[c] : 0.25) + spread;
        EXPECT_NEAR(rgb[(size_t(y) * width + x) * 3 + c], want, 5e-3 * spread + 1e-6) << x << "," << y << " " << c;
      }
}

TEST(Glare, NonFiniteInputStaysFinite) {
  std::vector<float> rgb(8 * 8 * 3, 0.5f);
  rgb[0] = std::numeric_limits<float>::quiet_NaN();
  rgb[4] = std::numeric_limits<float>::infinity();
  rgb[8] = -3;
  for (GlareMode mode : {GlareMode::Whole, GlareMode::Clipped}) {
    std::vector<float> out = rgb;
    apply_glare(out, 8, 8, {mode, 0.1});
    for (float v : out) EXPECT_TRUE(std::isfinite(v) && v >= 0) << v;
  }
}

TEST(Glare, Refusals) {
  std::vector<float> rgb(4 * 4 * 3, 2.0f);
  EXPECT_THAT(
      [&] {
        apply_glare(rgb, 4, 4, {GlareMode::Whole, 0});
      },
      testing::ThrowsMessage<std::invalid_argument>(testing::HasSubstr("a camera with a field of view")));
  EXPECT_THAT([] { parse_glare_mode("bloom"); }, testing::ThrowsMessage<std::invalid_argument>(testing::HasSubstr(
                                                     "glare must be none, whole or clipped, not 'bloom'")));
  EXPECT_EQ(parse_glare_mode("clipped"), GlareMode::Clipped);
  EXPECT_STREQ(glare_mode_name(GlareMode::Whole), "whole");
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
