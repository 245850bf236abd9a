#pragma once

#include <cmath>

namespace caustica {

// The sRGB electro-optical transfer function, IEC 61966-2-1: an encoded
// value in [0, 1] to linear.
inline float srgb_to_linear(float v) { return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); }

}  // namespace caustica
