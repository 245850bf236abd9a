#include "core/shapes/similarity.h"

#include <cmath>

namespace caustica {

std::optional<float> similarity_scale(const Transform& t) {
  const Vec3 sx = t.vector({1, 0, 0}), sy = t.vector({0, 1, 0}), sz = t.vector({0, 0, 1});
  const float scale = length(sx);
  const float tolerance = 1e-4f * scale;
  if (std::abs(length(sy) - scale) > tolerance || std::abs(length(sz) - scale) > tolerance ||
      std::abs(dot(sx, sy)) > tolerance * scale || std::abs(dot(sx, sz)) > tolerance * scale ||
      std::abs(dot(sy, sz)) > tolerance * scale)
    return std::nullopt;
  return scale;
}

}  // namespace caustica
