// RGB values lifted to spectra come back as themselves: the spectral
// estimate, run as a quadrature over stratified wavelengths, of a lifted
// emission is its RGB, and of a lifted reflectance (or a value above 1) lit
// by D65 (over D65's luminance) its RGB, within 0.2 % of the largest
// channel; black lifts to zero.

#include "core/spectral/rgb_lift.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/color/cie_tables.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// The estimate's mean over n stratified numbers of spectral_to_rgb(f(w)).
template <class Lifted>
Color mean_rgb(const Lifted& f, int n = 100000) {
  double sum[3] = {0, 0, 0};
  for (int k = 0; k < n; ++k) {
    const Wavelengths w = sample_wavelengths((k + 0.5f) / float(n));
    const Color rgb = spectral_to_rgb(f(w), w);
    for (int c = 0; c < 3; ++c) sum[c] += rgb[c] / n;
  }
  return {float(sum[0]), float(sum[1]), float(sum[2])};
}

Color d65_at(const Wavelengths& w) {
  return {float(cie_table_at(kCieD65, w.nm[0])), float(cie_table_at(kCieD65, w.nm[1])),
          float(cie_table_at(kCieD65, w.nm[2]))};
}

void expect_colour(Color got, Color expected, const char* what) {
  const float tolerance = 2e-3f * std::max({expected.r, expected.g, expected.b});
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], expected[c], tolerance) << what << ", channel " << c;
}

TEST(RgbLift, EmissionComesBackAsItsRgb) {
  for (const Color rgb : {Color(1, 1, 1), Color(17, 12, 4), Color(0.2f, 3, 0.5f), Color(0, 0, 2)})
    expect_colour(mean_rgb([&](const Wavelengths& w) { return lift_illuminant(rgb, w); }), rgb, "illuminant");
}

TEST(RgbLift, ReflectancesLitByD65ComeBackAsTheirRgb) {
  const Color white = mean_rgb(d65_at);
  const float d65_y = white.luminance();
  for (const Color rgb : {Color(0.63f, 0.065f, 0.05f), Color(0.14f, 0.45f, 0.091f), Color(0.73f, 0.73f, 0.73f),
                          Color(1, 0, 0), Color(0.1f, 0.2f, 0.9f)}) {
    const Color lit = mean_rgb([&](const Wavelengths& w) { return lift_reflectance(rgb, w) * d65_at(w); });
    expect_colour(lit * (1 / d65_y), rgb, "reflectance");
  }
  const Color above_one(2, 0.5f, 1);
  const Color lit = mean_rgb([&](const Wavelengths& w) { return lift_unbounded(above_one, w) * d65_at(w); });
  expect_colour(lit * (1 / d65_y), above_one, "unbounded");
}

TEST(RgbLift, BlackIsZero) {
  const Wavelengths w = sample_wavelengths(0.3f);
  EXPECT_EQ(lift_reflectance(Color(), w), Color());
  EXPECT_EQ(lift_unbounded(Color(), w), Color());
  EXPECT_EQ(lift_illuminant(Color(), w), Color());
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
