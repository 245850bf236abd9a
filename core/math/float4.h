#pragma once

// A Vec3 held in one 128-bit register (the fourth lane is 0 and unused), for
// the few hot spots where GCC's own vectorisation of Vec3 code shuffles and
// spills more than it computes: building a triangle's hit point costs half
// the instructions this way. Each lane does what the Vec3 code does, in the
// same order, so the results are those of Vec3 bit for bit.

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/math/vec.h"

namespace caustica {

using Float4 = float __attribute__((vector_size(16)));

inline Float4 to_float4(Vec3 v) { return Float4{v.x, v.y, v.z, 0}; }
inline Vec3 to_vec3(Float4 v) { return {v[0], v[1], v[2]}; }

inline Float4 abs(Float4 v) {
  using Bits = uint32_t __attribute__((vector_size(16)));
  return Float4(Bits(v) & 0x7fffffffu);
}
// std::max lane by lane: b where a < b, else a.
inline Float4 max(Float4 a, Float4 b) { return a < b ? b : a; }
inline float max_component(Float4 v) { return std::max({v[0], v[1], v[2]}); }
inline float dot(Float4 a, Float4 b) {
  const Float4 m = a * b;
  return m[0] + m[1] + m[2];
}
inline Float4 yzx(Float4 v) { return __builtin_shufflevector(v, v, 1, 2, 0, 3); }
inline Float4 zxy(Float4 v) { return __builtin_shufflevector(v, v, 2, 0, 1, 3); }
inline Float4 cross(Float4 a, Float4 b) { return yzx(a) * zxy(b) - zxy(a) * yzx(b); }
inline Float4 normalize(Float4 v) { return v / std::sqrt(dot(v, v)); }

}  // namespace caustica
