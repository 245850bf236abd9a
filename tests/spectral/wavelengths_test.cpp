// Wavelength sampling and the spectral estimate's conversion to colour.
//  - The visible density integrates to 1 (midpoint rule), and the hero and
//    both rotated wavelengths follow it: chi-square over 10 nm bins at 1%,
//    Sidak-corrected over the three, fixed seed.
//  - The estimator, run over stratified numbers (a quadrature), gives the
//    CIE's published figures: D65's white point (X, Y, Z) = (0.95047, 1,
//    1.08883), chromaticity (0.3127, 0.3290); a flat spectrum X = Y = Z; a
//    flat reflectance under D65 a Rec.709 grey; a 1 nm line at 580 nm the
//    chromaticity of the CIE table's entry there, (0.5125, 0.4866).

#include "core/spectral/wavelengths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/color/cie_tables.h"
#include "tests/support/chi2.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

TEST(Wavelengths, VisibleDensityIntegratesToOne) {
  const int n = 100000;
  double sum = 0;
  for (int i = 0; i < n; ++i)
    sum += visible_wavelength_pdf(kMinWavelengthNm + (i + 0.5f) * (kMaxWavelengthNm - kMinWavelengthNm) / n);
  EXPECT_NEAR(sum * (kMaxWavelengthNm - kMinWavelengthNm) / n, 1, 1e-5);
  EXPECT_EQ(visible_wavelength_pdf(kMinWavelengthNm - 1), 0);
  EXPECT_EQ(visible_wavelength_pdf(kMaxWavelengthNm + 1), 0);
}

TEST(Wavelengths, EachOfTheThreeFollowsTheDensity) {
  const int samples = 200000, bins = 47;
  const double alpha = test::sidak_alpha(0.01, 3);
  const double width = (kMaxWavelengthNm - kMinWavelengthNm) / bins;
  std::vector<double> expected(bins, 0.0);
  for (int b = 0; b < bins; ++b)
    for (int k = 0; k < 100; ++k)
      expected[size_t(b)] +=
          visible_wavelength_pdf(float(kMinWavelengthNm + (b + (k + 0.5) / 100) * width)) * width / 100 * samples;
  test::UniformSource u(7);
  std::vector<std::vector<double>> observed(3, std::vector<double>(bins, 0.0));
  for (int s = 0; s < samples; ++s) {
    const Wavelengths w = sample_wavelengths(u.next_1d());
    for (int i = 0; i < 3; ++i) {
      ASSERT_GE(w.nm[size_t(i)], kMinWavelengthNm);
      ASSERT_LE(w.nm[size_t(i)], kMaxWavelengthNm);
      ASSERT_EQ(w.pdf[size_t(i)], visible_wavelength_pdf(w.nm[size_t(i)]));
      const int b = std::min(bins - 1, int((w.nm[size_t(i)] - kMinWavelengthNm) / width));
      observed[size_t(i)][size_t(b)] += 1;
    }
  }
  for (int i = 0; i < 3; ++i) {
    const auto result = test::chi2_test_counts(observed[size_t(i)], expected);
    EXPECT_GT(result.p_value, alpha) << "wavelength " << i << ": " << result.report;
  }
}

// The estimator's mean over n stratified numbers, for the spectrum f.
template <class Spectrum>
std::array<double, 3> mean_xyz(const Spectrum& f, int n = 200000) {
  std::array<double, 3> sum{0, 0, 0};
  for (int k = 0; k < n; ++k) {
    const Wavelengths w = sample_wavelengths((k + 0.5f) / float(n));
    const Color values(float(f(w.nm[0])), float(f(w.nm[1])), float(f(w.nm[2])));
    const auto xyz = spectral_to_xyz(values, w);
    for (int c = 0; c < 3; ++c) sum[size_t(c)] += xyz[size_t(c)] / n;
  }
  return sum;
}

double d65(double nm) { return cie_table_at(kCieD65, nm); }

TEST(Wavelengths, D65GivesItsPublishedWhitePoint) {
  const auto xyz = mean_xyz(d65);
  EXPECT_NEAR(xyz[0] / xyz[1], 0.95047, 2e-3);
  EXPECT_NEAR(xyz[2] / xyz[1], 1.08883, 2e-3);
  const double sum = xyz[0] + xyz[1] + xyz[2];
  EXPECT_NEAR(xyz[0] / sum, 0.3127, 5e-4);
  EXPECT_NEAR(xyz[1] / sum, 0.3290, 5e-4);
}

TEST(Wavelengths, FlatSpectraAreEqualEnergyAndFlatReflectancesGrey) {
  const auto flat = mean_xyz([](double) { return 1.0; });
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(flat[size_t(c)], 1, 2e-3) << c;
  // A reflectance of 0.4 lit by D65, over D65's own Y.
  const double white_y = mean_xyz(d65)[1];
  std::array<double, 3> sum{0, 0, 0};
  const int n = 200000;
  for (int k = 0; k < n; ++k) {
    const Wavelengths w = sample_wavelengths((k + 0.5f) / float(n));
    const Color lit(float(0.4 * d65(w.nm[0])), float(0.4 * d65(w.nm[1])), float(0.4 * d65(w.nm[2])));
    const Color rgb = spectral_to_rgb(lit, w);
    for (int c = 0; c < 3; ++c) sum[size_t(c)] += rgb[c] / white_y / n;
  }
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(sum[size_t(c)], 0.4, 2e-3) << c;
}

TEST(Wavelengths, ALineAt580NmLandsOnTheTablesChromaticity) {
  const auto xyz = mean_xyz([](double nm) { return nm >= 579.5 && nm < 580.5 ? 1.0 : 0.0; }, 2000000);
  const double sum = xyz[0] + xyz[1] + xyz[2];
  EXPECT_NEAR(xyz[0] / sum, 0.9163 / (0.9163 + 0.87 + 0.00165), 1e-3);
  EXPECT_NEAR(xyz[1] / sum, 0.87 / (0.9163 + 0.87 + 0.00165), 1e-3);
  // Its luminance: y(580) over the integral of y (106.857 nm for these tables), times 1 nm.
  EXPECT_NEAR(xyz[1], 0.87 / 106.857, 2e-4);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
