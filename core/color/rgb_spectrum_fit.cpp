#include "core/color/rgb_spectrum_fit.h"

#include <algorithm>
#include <cmath>

#include "core/color/cie_tables.h"
#include "core/color/sigmoid_spectrum.h"
#include "core/color/xyz_to_rec709.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

// Per 5 nm sample: where it lies on the unit wavelength axis, and the
// Rec.709 colour a reflectance of 1 there alone adds.
struct Weights {
  std::array<double, kCieSamples> x;
  std::array<std::array<double, 3>, kCieSamples> rgb;

  Weights() {
    double norm = 0;
    for (int k = 0; k < kCieSamples; ++k) norm += kCieD65[size_t(k)] * kCieY[size_t(k)];
    for (int k = 0; k < kCieSamples; ++k) {
      const size_t i = size_t(k);
      x[i] = SigmoidSpectrum::unit_wavelength(kCieFirstNm + k * kCieStepNm);
      const double d = kCieD65[i] / norm;
      rgb[i] = xyz_to_rec709({kCieX[i] * d, kCieY[i] * d, kCieZ[i] * d});
    }
  }
};

const Weights& weights() {
  static const Weights w;
  return w;
}

// The colour of c and its derivatives by c (jacobian[channel][coefficient]).
std::array<double, 3> colour_and_jacobian(const std::array<double, 3>& c, double jacobian[3][3]) {
  const Weights& w = weights();
  std::array<double, 3> rgb{0, 0, 0};
  std::fill(&jacobian[0][0], &jacobian[0][0] + 9, 0.0);
  for (size_t k = 0; k < size_t(kCieSamples); ++k) {
    const double x = w.x[k], t = (c[0] * x + c[1]) * x + c[2];
    const double s = SigmoidSpectrum::sigmoid(t);
    const double ds = 0.5 / std::pow(1 + t * t, 1.5);
    const double dt[3] = {x * x, x, 1};
    for (int ch = 0; ch < 3; ++ch) {
      rgb[size_t(ch)] += s * w.rgb[k][size_t(ch)];
      for (int m = 0; m < 3; ++m) jacobian[ch][m] += ds * dt[m] * w.rgb[k][size_t(ch)];
    }
  }
  return rgb;
}

double largest_difference(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

// Solves a x = b by Gaussian elimination with partial pivoting; false when
// a is singular.
bool solve3(double a[3][3], std::array<double, 3> b, std::array<double, 3>& x) {
  int row[3] = {0, 1, 2};
  for (int col = 0; col < 3; ++col) {
    int pivot = col;
    for (int r = col + 1; r < 3; ++r)
      if (std::abs(a[row[r]][col]) > std::abs(a[row[pivot]][col])) pivot = r;
    std::swap(row[col], row[pivot]);
    const double p = a[row[col]][col];
    if (!(std::abs(p) > 1e-300)) return false;
    for (int r = col + 1; r < 3; ++r) {
      const double f = a[row[r]][col] / p;
      for (int k = col; k < 3; ++k) a[row[r]][k] -= f * a[row[col]][k];
      b[size_t(row[r])] -= f * b[size_t(row[col])];
    }
  }
  for (int col = 2; col >= 0; --col) {
    double v = b[size_t(row[col])];
    for (int k = col + 1; k < 3; ++k) v -= a[row[col]][k] * x[size_t(k)];
    x[size_t(col)] = v / a[row[col]][col];
  }
  return true;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

std::array<double, 3> sigmoid_reflectance_rgb(const std::array<double, 3>& c) {
  double unused[3][3];
  return colour_and_jacobian(c, unused);
}

SigmoidFit fit_sigmoid_reflectance(const std::array<double, 3>& rgb, const std::array<double, 3>& start) {
  std::array<double, 3> c = start;
  double jacobian[3][3];
  std::array<double, 3> now = colour_and_jacobian(c, jacobian);
  double error = largest_difference(now, rgb);
  for (int iteration = 0; iteration < 100 && error > 1e-7; ++iteration) {
    std::array<double, 3> step;
    if (!solve3(jacobian, {rgb[0] - now[0], rgb[1] - now[1], rgb[2] - now[2]}, step)) break;
    // Halve the step until the colour comes closer: far from the solution
    // the full Newton step overshoots where the sigmoid saturates.
    bool improved = false;
    for (double scale = 1; scale > 1e-4 && !improved; scale *= 0.5) {
      const std::array<double, 3> next = {c[0] + scale * step[0], c[1] + scale * step[1], c[2] + scale * step[2]};
      double next_jacobian[3][3];
      const std::array<double, 3> colour = colour_and_jacobian(next, next_jacobian);
      const double next_error = largest_difference(colour, rgb);
      if (next_error < error) {
        c = next;
        now = colour;
        error = next_error;
        std::copy(&next_jacobian[0][0], &next_jacobian[0][0] + 9, &jacobian[0][0]);
        improved = true;
      }
    }
    if (!improved) break;
  }
  return {c, error};
}

}  // namespace caustica
