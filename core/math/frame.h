#pragma once

#include <cmath>

#include "core/math/constants.h"
#include "core/math/vec.h"

namespace caustica {

// An orthonormal basis; local coordinates have the normal along +z.
struct Frame {
  Vec3 s{1, 0, 0}, t{0, 1, 0}, n{0, 0, 1};

  Frame() = default;
  Frame(Vec3 s_, Vec3 t_, Vec3 n_) : s(s_), t(t_), n(n_) {}

  // Branchless basis construction (Duff et al., JCGT 2017): continuous
  // everywhere except across n.z = 0's sign, and exact for unit n.
  static Frame from_normal(Vec3 n) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    return {Vec3(1 + sign * n.x * n.x * a, sign * b, -sign * n.x), Vec3(b, sign + n.y * n.y * a, -n.y), n};
  }

  // The frame around n whose s axis follows the tangent's direction (so
  // anisotropic materials and tangent-space maps follow the surface's
  // parametrisation); falls back to from_normal for a degenerate tangent.
  static Frame from_normal_and_tangent(Vec3 n, Vec3 tangent) {
    const Vec3 projected = tangent - n * dot(n, tangent);
    const float len2 = squared_length(projected);
    if (!(len2 > 1e-20f * squared_length(tangent)) || !std::isfinite(len2)) return from_normal(n);
    const Vec3 s = projected / std::sqrt(len2);
    return {s, cross(n, s), n};
  }

  Vec3 to_local(Vec3 v) const { return {dot(v, s), dot(v, t), dot(v, n)}; }
  Vec3 to_world(Vec3 v) const { return s * v.x + t * v.y + n * v.z; }
};

// The angle of (x, y) from the +x axis, in [0, 2 pi).
inline float azimuth(float x, float y) {
  const float phi = std::atan2(y, x);
  return phi < 0 ? phi + 2 * kPi : phi;
}

inline float cos_theta(Vec3 w) { return w.z; }
inline float abs_cos_theta(Vec3 w) { return std::abs(w.z); }
inline bool same_hemisphere(Vec3 a, Vec3 b) { return a.z * b.z > 0; }

}  // namespace caustica
