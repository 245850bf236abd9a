// RGB reflectances lifted to sigmoid spectra by the table the build fits.
// The oracle is apart from the fit: each spectrum is sampled every 1 nm,
// multiplied by D65 (tables interpolated linearly) and taken to Rec.709 by
// spectrum_to_rgb (tested on its own against published colours), then
// rescaled from equal-energy to D65 normalisation; the fit itself sums at
// the tables' 5 nm samples. Stated tolerance: every colour of a 17^3 grid
// over the cube, pure primaries included, round-trips within 0.002 per
// channel (0.0011 measured, most of it the two integrations' difference);
// every spectrum stays within [0, 1].

#include "core/color/rgb_spectrum_table.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/color/cie_tables.h"
#include "core/color/rgb_spectrum_fit.h"
#include "core/color/spectrum_to_rgb.h"
#include "tests/support/thrown_message.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using ::testing::HasSubstr;

double d65_at(double nm) {
  const double x = (nm - kCieFirstNm) / kCieStepNm;
  const int i = std::min(int(x), kCieSamples - 2);
  return kCieD65[size_t(i)] + (x - i) * (kCieD65[size_t(i) + 1] - kCieD65[size_t(i)]);
}

// The colour of reflectance s lit by D65, by the independent route above.
std::array<double, 3> lit_by_d65(const SigmoidSpectrum& s) {
  SampledSpectrum lit, d65;
  for (int nm = kCieFirstNm; nm <= kCieLastNm; ++nm) {
    lit.nm.push_back(nm);
    lit.values.push_back(s(nm) * d65_at(nm));
    d65.nm.push_back(nm);
    d65.values.push_back(d65_at(nm));
  }
  // spectrum_to_rgb divides by the integral of y; D65-normalised colours
  // divide by that of D65 y, which is D65's own luminance Y under the first.
  const Color white = spectrum_to_rgb(d65);
  const double d65_y = 0.2126 * white.r + 0.7152 * white.g + 0.0722 * white.b;
  const Color c = spectrum_to_rgb(lit);
  return {c.r / d65_y, c.g / d65_y, c.b / d65_y};
}

double largest_error(const std::array<double, 3>& a, const std::array<float, 3>& b) {
  return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

TEST(RgbSpectrumTable, ColoursRoundTripOverTheCube) {
  const RgbSpectrumTable& table = RgbSpectrumTable::built();
  double worst = 0;
  std::array<float, 3> worst_colour{};
  for (int r = 0; r <= 16; ++r)
    for (int g = 0; g <= 16; ++g)
      for (int b = 0; b <= 16; ++b) {
        const std::array<float, 3> rgb = {r / 16.0f, g / 16.0f, b / 16.0f};
        const SigmoidSpectrum s = table.lookup(rgb);
        for (int nm = kCieFirstNm; nm <= kCieLastNm; nm += 10) {
          ASSERT_GE(s(nm), 0) << r << " " << g << " " << b << " at " << nm;
          ASSERT_LE(s(nm), 1) << r << " " << g << " " << b << " at " << nm;
        }
        const double error = largest_error(lit_by_d65(s), rgb);
        if (error > worst) {
          worst = error;
          worst_colour = rgb;
        }
      }
  EXPECT_LT(worst, 0.002) << "at " << worst_colour[0] << ", " << worst_colour[1] << ", " << worst_colour[2];
}

TEST(RgbSpectrumTable, GreysAreFlat) {
  const RgbSpectrumTable& table = RgbSpectrumTable::built();
  for (float v : {0.0f, 0.18f, 0.5f, 0.9f, 1.0f}) {
    const SigmoidSpectrum s = table.lookup({v, v, v});
    for (int nm : {360, 500, 830}) EXPECT_NEAR(s(nm), v, 1e-6) << v << " at " << nm;
  }
  // Out of range and NaN channels are clamped into the cube first.
  const SigmoidSpectrum over = table.lookup({2.0f, std::nanf(""), -1.0f});
  const auto clamped = lit_by_d65(over);
  EXPECT_NEAR(clamped[0], 1, 0.02);
  EXPECT_NEAR(clamped[1], 0, 0.02);
  EXPECT_NEAR(clamped[2], 0, 0.02);
}

TEST(RgbSpectrumFit, NewtonMeetsTheColourFromAFlatStart) {
  for (const std::array<double, 3>& rgb : {std::array<double, 3>{0.7, 0.3, 0.2}, {0.2, 0.6, 0.3}, {0.25, 0.3, 0.8}}) {
    const SigmoidFit fit = fit_sigmoid_reflectance(rgb, {0, 0, 0});
    EXPECT_LT(fit.error, 1e-6);
    SigmoidSpectrum s;
    s.c = {float(fit.c[0]), float(fit.c[1]), float(fit.c[2])};
    const auto independent = lit_by_d65(s);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(independent[size_t(c)], rgb[size_t(c)], 1e-3) << c;
  }
}

std::filesystem::path temp_file(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "caustica_rgb_spectrum_table_test";
  std::filesystem::create_directories(dir);
  return dir / name;
}

TEST(RgbSpectrumTable, FilesRoundTripAndBadOnesAreRefused) {
  const RgbSpectrumTable small = RgbSpectrumTable::compute(6);
  const auto file = temp_file("small.bin");
  small.write(file);
  const RgbSpectrumTable back = RgbSpectrumTable::read(file);
  EXPECT_EQ(back.resolution(), 6);
  EXPECT_EQ(back.worst_fit_error(), small.worst_fit_error());
  for (const std::array<float, 3>& rgb : {std::array<float, 3>{0.3f, 0.6f, 0.1f}, {0.9f, 0.2f, 0.5f}})
    EXPECT_EQ(back.lookup(rgb).c, small.lookup(rgb).c);

  const auto read_error = [](const std::filesystem::path& f) {
    return test::thrown_message<std::runtime_error>([&] { RgbSpectrumTable::read(f); });
  };
  const auto bad = temp_file("bad.bin");
  std::ofstream(bad) << "CRGBSPEX";
  EXPECT_THAT(read_error(bad), HasSubstr("bad.bin: is not an RGB-to-spectrum table"));
  std::filesystem::resize_file(file, std::filesystem::file_size(file) - 4);
  EXPECT_THAT(read_error(file), HasSubstr("small.bin: holds "));
  EXPECT_THAT(read_error(file), HasSubstr("resolution 6 needs"));
  EXPECT_THAT(read_error(temp_file("missing.bin")), HasSubstr("missing.bin: cannot be opened"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
