#include "core/spectral/rgb_lift.h"

#include <algorithm>
#include <cmath>

#include "core/color/cie_tables.h"
#include "core/color/rgb_spectrum_table.h"
#include "core/color/spectrum_to_rgb.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

Color at_wavelengths(const SigmoidSpectrum& s, const Wavelengths& w, float scale = 1) {
  return {float(s(w.nm[0])) * scale, float(s(w.nm[1])) * scale, float(s(w.nm[2])) * scale};
}

// D65 over its luminance in the estimator's normalisation (the integral of
// D65 y over that of y), read with the tables' linear interpolation.
double d65_normalised(double nm) {
  static const double norm = [] {
    double d65_y = 0, y = 0;
    for (int k = 0; k + 1 < kCieSamples; ++k) {
      const size_t i = size_t(k);
      d65_y += 0.5 * (kCieD65[i] * kCieY[i] + kCieD65[i + 1] * kCieY[i + 1]);
      y += 0.5 * (kCieY[i] + kCieY[i + 1]);
    }
    return d65_y / y;
  }();
  return cie_table_at(kCieD65, nm) / norm;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

Color lift_reflectance(Color rgb, const Wavelengths& w) {
  return at_wavelengths(RgbSpectrumTable::built().lookup({rgb.r, rgb.g, rgb.b}), w);
}

Color lift_unbounded(Color rgb, const Wavelengths& w) {
  const float m = std::max({rgb.r, rgb.g, rgb.b});
  if (!(m > 0)) return {};
  const float scale = 2 * m;
  return at_wavelengths(RgbSpectrumTable::built().lookup({rgb.r / scale, rgb.g / scale, rgb.b / scale}), w, scale);
}

double lift_misfit(const SampledSpectrum& s, bool illuminant) {
  Color rgb = spectrum_to_rgb(s);
  if (!illuminant) {
    SampledSpectrum lit;
    for (int nm = kCieFirstNm; nm <= kCieLastNm; ++nm) {
      lit.nm.push_back(nm);
      lit.values.push_back(s.at(nm) * d65_normalised(nm));
    }
    rgb = spectrum_to_rgb(lit);
  }
  double difference = 0, total = 0;
  for (int nm = 400; nm <= 700; ++nm) {
    Wavelengths w;
    w.nm = {float(nm), float(nm), float(nm)};
    const double lifted = (illuminant ? lift_illuminant(rgb, w) : lift_reflectance(rgb, w)).r;
    const double v = s.at(nm);
    difference += std::abs(v - lifted);
    total += std::abs(v);
  }
  return total > 0 ? difference / total : 0;
}

Color lift_illuminant(Color rgb, const Wavelengths& w) {
  const Color s = lift_unbounded(rgb, w);
  return {float(s.r * d65_normalised(w.nm[0])), float(s.g * d65_normalised(w.nm[1])),
          float(s.b * d65_normalised(w.nm[2]))};
}

}  // namespace caustica
