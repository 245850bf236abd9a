#pragma once

#include "core/math/constants.h"
#include "core/math/vec.h"

namespace caustica {

struct Bounds3 {
  Vec3 lo{kInfinity, kInfinity, kInfinity};
  Vec3 hi{-kInfinity, -kInfinity, -kInfinity};

  void expand(Vec3 p) {
    lo = min(lo, p);
    hi = max(hi, p);
  }
  void expand(const Bounds3& b) {
    lo = min(lo, b.lo);
    hi = max(hi, b.hi);
  }
  bool empty() const { return lo.x > hi.x; }
  Vec3 center() const { return (lo + hi) * 0.5f; }
};

}  // namespace caustica
