#include "core/spectral/wavelengths.h"

#include <algorithm>
#include <cmath>

#include "core/color/cie_tables.h"
#include "core/color/xyz_to_rec709.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

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

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
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

Wavelengths pass_wavelengths(uint64_t pass, uint64_t seed) {
  // splitmix64 of the seed, for the offset.
  uint64_t z = seed + 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  z ^= z >> 31;
  const double offset = double(z >> 11) * 0x1p-53;
  const double u = std::fmod(offset + double(pass) * 0.6180339887498949, 1.0);
  return sample_wavelengths(float(std::min(u, 0x1.fffffep-1)));
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
