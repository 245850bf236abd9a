#pragma once

#include <cstddef>
#include <vector>

#include "core/math/animated_transform.h"

namespace caustica {

// Something carried rigidly over the shutter (a moving camera or light):
// from where `placement` puts its still self to where the interpolated
// keys put it at each time. A rigid map keeps lengths and angles, so what
// the still object computes holds for the moving one, carried.
class RigidMotion {
 public:
  RigidMotion(const std::vector<Transform>& keys, const Transform& placement)
      : keys_(keys), placement_inverse_(placement.inverse()) {}

  // The map from the still placement to the one at `time` (see Ray::time).
  Transform at(float time) const { return keys_.at(time) * placement_inverse_; }
  // The number (from 2) of the first key whose scale or shear differs from
  // the first key's, or 0 when the motion is rigid.
  size_t rescaled_key() const { return keys_.first_rescaled_key(); }

 private:
  AnimatedTransform keys_;
  Transform placement_inverse_;
};

// A point's error bound carried by a rigid map to `moved`: its length in
// every axis (the map keeps it, whatever its direction), plus the map's
// float rounding there.
Vec3 carried_error(Vec3 error, Vec3 moved);

// A normal carried by a rigid map; zero (no normal) stays zero.
Vec3 carried_normal(const Transform& m, Vec3 n);

}  // namespace caustica
