#pragma once

#include "core/math/constants.h"
#include "core/math/vec.h"

namespace caustica {

struct Ray {
  Vec3 o, d;
  float t_max = kInfinity;
  float t_min = 0;  // camera rays start at the near clipping plane
  // When along the shutter interval the ray is traced: 0 as it opens, 1 as
  // it closes. Every ray of a path shares its path's time.
  float time = 0;

  Vec3 at(float t) const { return o + d * t; }
};

}  // namespace caustica
