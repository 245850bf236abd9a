#pragma once

#include <algorithm>
#include <vector>

namespace caustica {

// A spectrum given at wavelengths (nm, increasing), linear in between and
// zero outside, as a scene's <spectrum value="400:0.34, 404:0.45, ..."/>
// or a .spd file gives it.
struct SampledSpectrum {
  std::vector<double> nm, values;

  double at(double wavelength) const {
    if (nm.empty() || wavelength < nm.front() || wavelength > nm.back()) return 0;
    if (nm.size() == 1) return values.front();
    const size_t i = std::max<size_t>(1, size_t(std::lower_bound(nm.begin(), nm.end(), wavelength) - nm.begin()));
    const double t = (wavelength - nm[i - 1]) / (nm[i] - nm[i - 1]);
    return values[i - 1] * (1 - t) + values[i] * t;
  }
};

}  // namespace caustica
