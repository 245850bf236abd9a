#pragma once

#include "core/image/image_output.h"

namespace caustica {

// The epsilon of the relative squared error (x - ref)^2 / (ref^2 + epsilon):
// it keeps black pixels from dominating the mean.
inline constexpr double kRelMseEpsilon = 1e-2;

// The error an image expects of itself from its variance layers (variance.R,
// .G, .B: the variance of each pixel's estimate): the mean variance, and the
// mean variance / (x^2 + epsilon). For an unbiased render these are its
// expected MSE and relative MSE. Zero when the image has no variance layers.
struct EstimatedError {
  double mse = 0, rel_mse = 0;
  bool known = false;  // the image has variance layers
};
EstimatedError estimated_error(const Image& image, double rel_epsilon = kRelMseEpsilon);

// The error of a render against a reference over the beauty channels R, G, B,
// averaged over pixels and channels.
//
// The reference is a Monte Carlo estimate too. If it is unbiased and
// independent of the render, E[(x - ref)^2] = E[(x - truth)^2] + Var[ref]:
// the measured squared error overstates the render's true one by the
// reference's variance. The *_corrected values subtract the reference's
// estimated_error() (mean variance, or mean variance / (ref^2 + epsilon)) so
// that what remains is the render's own error; they may come out slightly
// negative when the render is as accurate as the reference. The mean
// absolute error has no such additive form and is reported as measured.
struct ErrorMetrics {
  double mse = 0, mse_corrected = 0;
  double rel_mse = 0, rel_mse_corrected = 0;
  double mae = 0;
  EstimatedError reference, image;  // each image's estimate of its own error
};

// Throws std::invalid_argument when the sizes differ or R, G, B are missing.
ErrorMetrics compare_images(const Image& image, const Image& reference, double rel_epsilon = kRelMseEpsilon);

}  // namespace caustica
