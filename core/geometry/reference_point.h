#pragma once

#include "core/math/vec.h"

namespace caustica {

// A point that receives light or importance, as emitters and cameras need
// to see it when they sample a direction toward it.
struct ReferencePoint {
  Vec3 p, p_error, n;  // n is zero for points not on a surface
};

}  // namespace caustica
