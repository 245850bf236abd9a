#pragma once

#include <cstdint>

#include "core/math/vec.h"

namespace caustica {

// Where a line o + t d crosses the boundary of a solid: at t (t < 0 lies
// behind o), on the surface of leaf `leaf` of a csg tree (0 for a plain
// shape) at its primitive `prim` and shape-defined uv, entering the solid
// or leaving it.
struct BoundaryCrossing {
  double t;
  uint32_t leaf;
  uint32_t prim;
  Vec2 uv;
  bool entering;
};

}  // namespace caustica
