// Images larger than one band are written a band of rows at a time; what
// comes back must be what one write of the whole image would have made.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "core/image/image_input.h"
#include "core/image/image_output.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// 1024 x 700 x 3 floats: bands of about a million values hold 341 rows, so
// the image takes three bands, the last one short.
Image tall_image() {
  Image image{1024, 700, {"R", "G", "B"}, {}};
  image.pixels.resize(size_t(image.width) * image.height * 3);
  for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = float(i % 7919) * 0.125f + float(i / 7919);
  return image;
}

TEST(BandedOutput, ExrOfSeveralBandsComesBackExactly) {
  const auto path = std::filesystem::temp_directory_path() / "caustica_banded.exr";
  const Image image = tall_image();
  int calls = 0;
  ImageRows rows = rows_of(image);
  const auto fill = rows.fill;
  rows.fill = [&](int y_begin, int y_end, float* out) {
    ++calls;
    fill(y_begin, y_end, out);
  };
  write_exr(path, rows, {}, false);
  EXPECT_EQ(calls, 3);
  const Image back = read_image(path);
  ASSERT_EQ(back.channels, image.channels);
  EXPECT_EQ(back.pixels, image.pixels);
}

// Each 8-bit pixel's dither is a function of its row and column, so a band
// quantised on its own must give the values of the whole image's rows.
TEST(BandedOutput, PngOfSeveralBandsEqualsTheWholeImageQuantised) {
  constexpr int kWidth = 256, kHeight = 700;  // bands of 341 rows
  std::vector<float> rgb(size_t(kWidth) * kHeight * 3);
  for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = float((i * 2654435761u) % 1000) / 999;
  for (int bits : {8, 16}) {
    const auto path = std::filesystem::temp_directory_path() / "caustica_banded.png";
    write_png(path, kWidth, kHeight, rgb, bits);
    const Image back = read_image(path);
    const std::vector<uint16_t> whole = quantize(rgb, kWidth, bits);
    ASSERT_EQ(back.pixels.size(), whole.size());
    const float levels = bits == 8 ? 255.0f : 65535.0f;
    size_t differing = 0;
    for (size_t i = 0; i < whole.size(); ++i) differing += std::lround(back.pixels[i] * levels) != whole[i];
    EXPECT_EQ(differing, 0u) << bits << " bits";
  }
}

TEST(BandedOutput, QuantisingFromARowOnEqualsThoseRowsOfTheWhole) {
  constexpr int kWidth = 64;
  std::vector<float> rgb(size_t(kWidth) * 10 * 3);
  for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = 0.5f + 0.3f * std::sin(float(i));
  const std::vector<uint16_t> whole = quantize(rgb, kWidth, 8);
  const std::span<const float> rows(rgb.data() + 4 * kWidth * 3, 6 * kWidth * 3);
  const std::vector<uint16_t> tail = quantize(rows, kWidth, 8, 4);
  EXPECT_TRUE(std::equal(tail.begin(), tail.end(), whole.begin() + 4 * kWidth * 3));
  EXPECT_NE(quantize(rows, kWidth, 8, 0), tail);
}

TEST(BandedOutput, ExtremeValuesAreCountedInEveryBand) {
  Image image = tall_image();
  for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = std::fmod(image.pixels[i], 100.0f);
  image.pixels[5] = 65505;                                                    // first band
  image.pixels[size_t(400) * 1024 * 3] = -1e6f;                               // second
  image.pixels.back() = std::numeric_limits<float>::max();                    // last
  image.pixels[size_t(690) * 1024 * 3] = -std::numeric_limits<float>::max();  // last
  const ExtremeValues n = count_extreme_values(rows_of(image));
  EXPECT_EQ(n.beyond_half, 4u);
  EXPECT_EQ(n.at_float_limit, 2u);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
