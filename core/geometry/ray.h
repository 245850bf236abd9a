#pragma once

#include "core/math/constants.h"
#include "core/math/vec.h"

namespace caustica {

struct Ray {
  Vec3 o, d;
  float t_max = kInfinity;
  float t_min = 0;  // camera rays start at the near clipping plane

  Vec3 at(float t) const { return o + d * t; }
};

}  // namespace caustica
