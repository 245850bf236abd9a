#pragma once

#include "core/math/vec.h"

namespace caustica {

// A point that receives light or importance, as emitters and cameras need
// to see it when they sample a direction toward it.
struct ReferencePoint {
  Vec3 p, p_error, n;  // n is zero for points not on a surface
  float time = 0;      // the path's (see Ray::time): where a moving camera stands
};

}  // namespace caustica
