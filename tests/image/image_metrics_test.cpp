#include "core/image/image_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// Two pixels, worked by hand:
//   image      (1, 2, 3)  (0, 0, 0.5)
//   reference  (1, 1, 1)  (0, 0.5, 0)   variance (0.01, 0.02, 0.03)  (0, 0.04, 0)
//   difference (0, 1, 2)  (0, -0.5, 0.5)
const Image kImage{2, 1, {"R", "G", "B"}, {1, 2, 3, 0, 0, 0.5f}};
const Image kReference{2,
                       1,
                       {"R", "G", "B", "variance.R", "variance.G", "variance.B"},
                       {1, 1, 1, 0.01f, 0.02f, 0.03f, 0, 0.5f, 0, 0, 0.04f, 0}};

TEST(ImageMetrics, HandComputedErrors) {
  const ErrorMetrics m = compare_images(kImage, kReference);
  // Squared differences 0 + 1 + 4 + 0 + 0.25 + 0.25 over six values.
  EXPECT_NEAR(m.mse, 5.5 / 6, 1e-7);
  // Absolute differences 0 + 1 + 2 + 0 + 0.5 + 0.5.
  EXPECT_NEAR(m.mae, 4.0 / 6, 1e-7);
  // Denominators ref^2 + 0.01: 1.01 for the first pixel, 0.01, 0.26, 0.01 for the second.
  EXPECT_NEAR(m.rel_mse, (1 / 1.01 + 4 / 1.01 + 0.25 / 0.26 + 0.25 / 0.01) / 6, 1e-6);
  // The reference's own error: its mean variance, and the variance over the same denominators.
  EXPECT_TRUE(m.reference.known);
  EXPECT_NEAR(m.reference.mse, 0.1 / 6, 1e-8);
  EXPECT_NEAR(m.reference.rel_mse, ((0.01 + 0.02 + 0.03) / 1.01 + 0.04 / 0.26) / 6, 1e-7);
  EXPECT_NEAR(m.mse_corrected, 5.5 / 6 - 0.1 / 6, 1e-7);
  EXPECT_NEAR(m.rel_mse_corrected, m.rel_mse - m.reference.rel_mse, 1e-9);
  EXPECT_FALSE(m.image.known);  // the image has no variance layers
}

TEST(ImageMetrics, RelativeEpsilonIsAParameter) {
  const ErrorMetrics m = compare_images(kImage, kReference, 1.0);
  EXPECT_NEAR(m.rel_mse, (1 / 2.0 + 4 / 2.0 + 0.25 / 1.25 + 0.25 / 1.0) / 6, 1e-6);
}

TEST(ImageMetrics, ChannelsAreFoundByName) {
  // OpenEXR files come back with their channels in another order.
  const Image shuffled{2, 1, {"B", "G", "R"}, {3, 2, 1, 0.5f, 0, 0}};
  EXPECT_NEAR(compare_images(shuffled, kReference).mse, 5.5 / 6, 1e-7);
}

TEST(ImageMetrics, IdenticalImagesHaveNoError) {
  const ErrorMetrics m = compare_images(kReference, kReference);
  EXPECT_EQ(m.mse, 0);
  EXPECT_EQ(m.rel_mse, 0);
  EXPECT_EQ(m.mae, 0);
  EXPECT_LT(m.mse_corrected, 0);  // the correction may overshoot once the error is the reference's noise
}

TEST(ImageMetrics, EstimatedErrorOfAnImage) {
  const EstimatedError e = estimated_error(kReference);
  EXPECT_TRUE(e.known);
  EXPECT_NEAR(e.mse, 0.1 / 6, 1e-8);
  EXPECT_FALSE(estimated_error(kImage).known);
  EXPECT_EQ(estimated_error(kImage).mse, 0);
}

TEST(ImageMetrics, RejectsMismatchedImages) {
  const Image small{1, 1, {"R", "G", "B"}, {0, 0, 0}};
  EXPECT_THROW(
      {
        try {
          compare_images(small, kReference);
        } catch (const std::invalid_argument& e) {
          EXPECT_STREQ(e.what(), "the image is 1x1 but the reference is 2x1");
          throw;
        }
      },
      std::invalid_argument);
  const Image no_green{2, 1, {"R", "B", "A"}, {0, 0, 0, 0, 0, 0}};
  EXPECT_THROW(compare_images(no_green, kReference), std::invalid_argument);
}

std::string error_of(const Image& image, const Image& reference) {
  try {
    compare_images(image, reference);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

// Non-finite values would make every metric non-finite: the first pixel
// holding one is named, with the count.
TEST(ImageMetrics, NonFiniteValuesAreNamed) {
  Image image{3, 2, {"R", "G", "B"}, std::vector<float>(18, 0.5f)};
  const Image reference{3, 2, {"R", "G", "B"}, std::vector<float>(18, 0.5f)};
  image.pixels[(1 * 3 + 2) * 3 + 1] = NAN;       // (2, 1) G
  image.pixels[(1 * 3 + 0) * 3 + 2] = INFINITY;  // (0, 1) B, earlier in the scan
  EXPECT_EQ(error_of(image, reference), "the image has 2 non-finite values, the first at pixel (0, 1) in B (inf)");
  EXPECT_EQ(error_of(reference, image), "the reference has 2 non-finite values, the first at pixel (0, 1) in B (inf)");
  image.pixels[(1 * 3 + 0) * 3 + 2] = 3e38f;  // large but finite
  EXPECT_EQ(error_of(image, reference), "the image has 1 non-finite value, the first at pixel (2, 1) in G (nan)");
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
