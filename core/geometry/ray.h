#pragma once

#include "core/math/constants.h"
#include "core/math/vec.h"

namespace caustica {

struct Ray {
  Vec3 o, d;
  float t_max = kInfinity;

  Vec3 at(float t) const { return o + d * t; }
};

}  // namespace caustica
