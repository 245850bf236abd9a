#pragma once

#include <cmath>

#include "core/geometry/ray.h"
#include "core/math/next_float.h"

namespace caustica {

// Moves a surface point off its surface, toward the side `w` points to, by
// just more than the point's floating-point error bound `p_error`. A ray
// leaving from the result cannot re-hit the surface it left, whatever the
// scene's scale, and no epsilon is tuned per scene.
inline Vec3 offset_ray_origin(Vec3 p, Vec3 p_error, Vec3 n, Vec3 w) {
  const float d = dot(abs(n), p_error);
  Vec3 offset = n * d;
  if (dot(w, n) < 0) offset = -offset;
  Vec3 po = p + offset;
  // Round away from p so the offset survives the addition's rounding.
  for (int i = 0; i < 3; ++i) {
    if (offset[i] > 0)
      po[i] = next_float_up(po[i]);
    else if (offset[i] < 0)
      po[i] = next_float_down(po[i]);
  }
  return po;
}

}  // namespace caustica
