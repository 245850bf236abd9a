#pragma once

#include <cmath>
#include <optional>

#include "core/geometry/reference_point.h"
#include "core/lights/emitter.h"

namespace caustica {

// The light a point light at `position` sends to `ref`, falling off with
// the squared distance; `intensity(d)` is its intensity along the world
// direction d leaving the light. A delta: taken with density one.
template <class Intensity>
std::optional<LiSample> point_light_Li(Vec3 position, const ReferencePoint& ref, Intensity intensity) {
  Vec3 wi = position - ref.p;
  const float dist2 = squared_length(wi);
  if (dist2 == 0) return std::nullopt;
  wi = wi / std::sqrt(dist2);
  const Color I = intensity(-wi);
  if (I.is_black()) return std::nullopt;
  return LiSample{wi, I / dist2, 1, true, position, {}, {}, false};
}

}  // namespace caustica
