#pragma once

#include <vector>

#include "core/image/even_kernel.h"

namespace caustica {

// The eye's photopic point spread function of Spencer, Shirley, Zimmerman
// and Greenberg ("Physically-based glare effects for digital images", 1995):
// with theta the angle from the point in degrees,
//   f0 = 2.61e6 exp(-(theta / 0.02)^2)
//   f1 = 20.91 / (theta + 0.02)^3
//   f2 = 72.37 / (theta + 0.02)^2
//   psf = 0.384 f0 + 0.478 f1 + 0.138 f2,
// per steradian (f0 and f1 each integrate to one over the plane; f2's tail
// falls as 1 / theta^2 and its integral grows without bound).
double glare_psf(double theta_degrees);

// The PSF integrated over the pixel at offset (dx, dy) from the point, in
// square degrees, for |dx| < width and |dy| < height: the core's Gaussian
// in closed form (it separates into error functions), the tails by the
// midpoint rule on cells small beside their distance from the point.
class PsfPixelIntegral {
 public:
  PsfPixelIntegral(int width, int height, double degrees_per_pixel);
  double operator()(int dx, int dy) const;

 private:
  double d_;
  std::vector<double> core_x_, core_y_;
};

// The PSF integrated over each pixel of a width x height image whose pixels
// span `degrees_per_pixel` (the small-angle approximation: the view is
// taken as flat), with offsets reaching across the whole image, then
// normalised so the whole kernel sums to one: a pixel's light is
// redistributed, never made or lost.
EvenKernel glare_kernel(int width, int height, double degrees_per_pixel);

}  // namespace caustica
