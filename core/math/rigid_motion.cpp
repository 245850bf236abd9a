#include "core/math/rigid_motion.h"

#include "core/math/constants.h"

namespace caustica {

Vec3 carried_error(Vec3 error, Vec3 moved) {
  const float e = length(error) + gamma(16) * max_component(abs(moved));
  return {e, e, e};
}

Vec3 carried_normal(const Transform& m, Vec3 n) { return n == Vec3() ? n : normalize(m.vector(n)); }

}  // namespace caustica
