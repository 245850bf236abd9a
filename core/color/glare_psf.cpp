#include "core/color/glare_psf.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

constexpr double kCoreWidth = 0.02;  // degrees: f0's width and f1's, f2's offset
double core(double theta) { return 2.61e6 * std::exp(-(theta / kCoreWidth) * (theta / kCoreWidth)); }
double tails(double theta) {
  const double t = theta + kCoreWidth;
  return 0.478 * 20.91 / (t * t * t) + 0.138 * 72.37 / (t * t);
}

// The core's integral over pixel column (or row) `i` along one axis: the
// integral over a pixel is 2.61e6 times the product of its two axes' factors.
std::vector<double> core_factors(int n, double d) {
  const double half_width = kCoreWidth * std::sqrt(std::numbers::pi) / 2;
  std::vector<double> factors(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i)
    factors[size_t(i)] = half_width * (std::erf((i + 0.5) * d / kCoreWidth) - std::erf((i - 0.5) * d / kCoreWidth));
  return factors;
}

// The tails' integral over the pixel at offset (dx, dy) >= 0 by the
// midpoint rule on n x n cells, n chosen so a cell stays below 1/32 of the
// distance scale (theta + 0.02 degrees) of the pixel's nearest point.
double tails_over_pixel(int dx, int dy, double d) {
  const double nearest = std::hypot(std::max(0.0, dx - 0.5), std::max(0.0, dy - 0.5)) * d;
  const int n = std::clamp(int(std::ceil(32 * d / (nearest + kCoreWidth))), 1, 1024);
  const double cell = d / n;
  double sum = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      sum += tails(std::hypot((dx - 0.5) * d + (i + 0.5) * cell, (dy - 0.5) * d + (j + 0.5) * cell));
  return sum * cell * cell;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

double glare_psf(double theta_degrees) { return 0.384 * core(theta_degrees) + tails(theta_degrees); }

PsfPixelIntegral::PsfPixelIntegral(int width, int height, double degrees_per_pixel)
    : d_(degrees_per_pixel), core_x_(core_factors(width, d_)), core_y_(core_factors(height, d_)) {}

double PsfPixelIntegral::operator()(int dx, int dy) const {
  dx = std::abs(dx);
  dy = std::abs(dy);
  return 0.384 * 2.61e6 * core_x_[size_t(dx)] * core_y_[size_t(dy)] + tails_over_pixel(dx, dy, d_);
}

EvenKernel glare_kernel(int width, int height, double degrees_per_pixel) {
  EvenKernel kernel{width, height, std::vector<double>(size_t(width) * size_t(height))};
  const PsfPixelIntegral integral(width, height, degrees_per_pixel);
  // In square degrees; the scale to steradians cancels in the normalisation.
  tbb::parallel_for(0, height, [&](int dy) {
    for (int dx = 0; dx < width; ++dx) kernel.quadrant[size_t(dy) * width + dx] = integral(dx, dy);
  });
  const double total = kernel.total();
  for (double& w : kernel.quadrant) w /= total;
  return kernel;
}

}  // namespace caustica
