#pragma once

#include <array>

namespace caustica {

// Fitting sigmoid spectra (core/color/sigmoid_spectrum.h) to RGB
// reflectances. A reflectance's colour here is the one it shows lit by
// D65 and seen by the CIE 1931 observer, in linear Rec.709: the sums over
// the CIE tables' 5 nm samples of s D65 (x, y, z), over that of D65 y.
// Under this convention a reflectance of 1 everywhere is RGB white (to the
// tables' rounding).

// The colour of the sigmoid spectrum with coefficients c.
std::array<double, 3> sigmoid_reflectance_rgb(const std::array<double, 3>& c);

struct SigmoidFit {
  std::array<double, 3> c;
  double error;  // the largest difference, over the channels, between its colour and the target
};

// The coefficients whose colour is `rgb` (each channel in [0, 1]), by a
// damped Newton iteration from `start`. Colours no spectrum within [0, 1]
// shows (pure primaries at full strength are at that edge) end with the
// closest the iteration reaches, their error saying how close.
SigmoidFit fit_sigmoid_reflectance(const std::array<double, 3>& rgb, const std::array<double, 3>& start);

}  // namespace caustica
