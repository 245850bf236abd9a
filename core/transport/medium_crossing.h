#pragma once

#include "core/geometry/interaction.h"
#include "core/shapes/shape.h"

namespace caustica {

class Medium;

// The medium a ray leaving `si` along d travels in, `current` being the
// one it arrived through: a shape that bounds media decides by the side d
// points to; any other shape leaves the ray in the medium it was in.
inline const Medium* medium_after(const SurfaceInteraction& si, const Medium* current, Vec3 d) {
  const Shape& shape = *si.shape;
  if (!shape.bounds_media()) return current;
  return dot(d, si.ng) > 0 ? shape.exterior() : shape.interior();
}

}  // namespace caustica
