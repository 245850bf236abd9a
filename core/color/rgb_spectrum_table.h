#pragma once

#include <array>
#include <filesystem>
#include <vector>

#include "core/color/sigmoid_spectrum.h"

namespace caustica {

// Sigmoid spectra (core/color/sigmoid_spectrum.h) fitted to RGB
// reflectances over the whole cube [0, 1]^3 in advance, so that lifting a
// colour to a spectrum while rendering is a table lookup. As in Jakob and
// Hanika 2019, a colour is indexed by its largest channel z (three tables,
// one per channel that is largest) and the other two divided by z; z's
// samples crowd toward 0 and 1 (a double smoothstep), where spectra change
// fastest. Coefficients are interpolated trilinearly between samples.
//
// The table is computed at build time by make_rgb_spectrum_table (the
// project's own fit, core/color/rgb_spectrum_fit.h) and read once when first
// needed.
class RgbSpectrumTable {
 public:
  // Fits every entry of a table with `resolution` samples along each axis,
  // each from its neighbour's coefficients, outward from grey.
  static RgbSpectrumTable compute(int resolution);

  // Binary form: "CRGBSPEC", resolution, the z samples, the coefficients,
  // all little-endian 32-bit. read() checks each part and throws
  // std::runtime_error naming the file.
  void write(const std::filesystem::path& file) const;
  static RgbSpectrumTable read(const std::filesystem::path& file);

  // The table this build made.
  static const RgbSpectrumTable& built();
  // Where built() reads it from (see data_file).
  static std::filesystem::path built_path();

  // The spectrum of reflectance rgb, each channel clamped to [0, 1]. Greys
  // (and black) get their flat spectrum exactly.
  SigmoidSpectrum lookup(std::array<float, 3> rgb) const;

  int resolution() const { return resolution_; }
  // The largest fit error of any entry, over the channels of its colour.
  float worst_fit_error() const { return worst_error_; }

 private:
  size_t index(int largest, int zi, int yi, int xi) const {
    return (((size_t(largest) * size_t(resolution_) + size_t(zi)) * size_t(resolution_) + size_t(yi)) *
                size_t(resolution_) +
            size_t(xi)) *
           3;
  }

  int resolution_ = 0;
  float worst_error_ = 0;
  std::vector<float> z_;             // resolution samples of the largest channel, increasing from 0 to 1
  std::vector<float> coefficients_;  // 3 x resolution^3 x 3
};

}  // namespace caustica
