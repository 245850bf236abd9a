#pragma once

#include <array>
#include <cmath>

namespace caustica {

// A smooth spectrum bounded in [0, 1] by three coefficients (the
// sigmoid-polynomial model of Jakob and Hanika 2019):
//   s(lambda) = S(c0 x^2 + c1 x + c2),  S(t) = 1/2 + t / (2 sqrt(1 + t^2)),
// with x = (lambda - 360 nm) / 470 nm running over [0, 1] across the
// visible range, which keeps the coefficients of usual colours near 1.
struct SigmoidSpectrum {
  std::array<float, 3> c{0, 0, 0};

  static double sigmoid(double t) { return std::isinf(t) ? (t > 0 ? 1.0 : 0.0) : 0.5 + t / (2 * std::sqrt(1 + t * t)); }
  static double unit_wavelength(double nm) { return (nm - 360.0) / 470.0; }

  double operator()(double nm) const {
    const double x = unit_wavelength(nm);
    return sigmoid((double(c[0]) * x + double(c[1])) * x + double(c[2]));
  }
};

}  // namespace caustica
