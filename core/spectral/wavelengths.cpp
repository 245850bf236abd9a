#include "core/spectral/wavelengths.h"

#include <cmath>

#include "core/color/cie_tables.h"
#include "core/color/xyz_to_rec709.h"

namespace caustica {

namespace {

constexpr double kSharpness = 0.0072, kCentreNm = 538;

double tanh_at(double nm) { return std::tanh(kSharpness * (nm - kCentreNm)); }

// The integral of y over the tables' range, by the same linear
// interpolation the estimator reads them with.
double y_integral() {
  static const double integral = [] {
    double sum = 0;
    for (int k = 0; k + 1 < kCieSamples; ++k) sum += 0.5 * (kCieY[size_t(k)] + kCieY[size_t(k) + 1]) * kCieStepNm;
    return sum;
  }();
  return integral;
}

}  // namespace

float visible_wavelength_pdf(float nm) {
  if (!(nm >= kMinWavelengthNm && nm <= kMaxWavelengthNm)) return 0;
  const double norm = (tanh_at(kMaxWavelengthNm) - tanh_at(kMinWavelengthNm)) / kSharpness;
  const double c = std::cosh(kSharpness * (nm - kCentreNm));
  return float(1 / (c * c * norm));
}

float sample_visible_wavelength(float u) {
  const double lo = tanh_at(kMinWavelengthNm), hi = tanh_at(kMaxWavelengthNm);
  const double nm = kCentreNm + std::atanh(lo + double(u) * (hi - lo)) / kSharpness;
  return float(std::fmin(std::fmax(nm, kMinWavelengthNm), kMaxWavelengthNm));
}

Wavelengths sample_wavelengths(float u) {
  Wavelengths w;
  for (int i = 0; i < 3; ++i) {
    float ui = u + float(i) / 3;
    if (ui >= 1) ui -= 1;
    w.nm[size_t(i)] = sample_visible_wavelength(ui);
    w.pdf[size_t(i)] = visible_wavelength_pdf(w.nm[size_t(i)]);
  }
  return w;
}

void terminate_secondaries(Wavelengths& w) {
  if (secondaries_terminated(w)) return;
  w.pdf[0] /= 3;
  w.pdf[1] = w.pdf[2] = 0;
}

bool secondaries_terminated(const Wavelengths& w) { return w.pdf[1] == 0 && w.pdf[2] == 0; }

std::array<double, 3> spectral_to_xyz(Color values, const Wavelengths& w) {
  std::array<double, 3> xyz{0, 0, 0};
  for (int i = 0; i < 3; ++i) {
    const double pdf = w.pdf[size_t(i)];
    if (!(pdf > 0)) continue;
    const double nm = w.nm[size_t(i)], v = double(values[i]) / pdf;
    xyz[0] += v * cie_table_at(kCieX, nm);
    xyz[1] += v * cie_table_at(kCieY, nm);
    xyz[2] += v * cie_table_at(kCieZ, nm);
  }
  const double scale = 1 / (3 * y_integral());
  for (double& c : xyz) c *= scale;
  return xyz;
}

Color spectral_to_rgb(Color values, const Wavelengths& w) {
  const auto rgb = xyz_to_rec709(spectral_to_xyz(values, w));
  return {float(rgb[0]), float(rgb[1]), float(rgb[2])};
}

}  // namespace caustica
