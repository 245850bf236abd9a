#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

namespace caustica {

// The neighbouring floats of v, as std::nextafter(v, +-infinity) gives
// them, by stepping v's bits: libm's nextafter is a call for every ray
// origin offset.
inline float next_float_up(float v) {
  if (std::isinf(v) && v > 0) return v;
  if (v == 0) return std::bit_cast<float>(uint32_t(1));
  const uint32_t bits = std::bit_cast<uint32_t>(v);
  return std::bit_cast<float>(v > 0 ? bits + 1 : bits - 1);
}

inline float next_float_down(float v) {
  if (std::isinf(v) && v < 0) return v;
  if (v == 0) return -std::bit_cast<float>(uint32_t(1));
  const uint32_t bits = std::bit_cast<uint32_t>(v);
  return std::bit_cast<float>(v > 0 ? bits - 1 : bits + 1);
}

}  // namespace caustica
