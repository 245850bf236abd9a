#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "core/math/transform.h"

namespace caustica {

// One key of a motion: the transform that holds at `time` (normalised to
// the shutter: 0 as it opens, 1 as it closes).
struct TransformKey {
  double time = 0;
  Transform transform;
};

// An affine map split as M = T R S: S upper triangular (scale on its
// diagonal, shear above it), R a rotation as a unit quaternion (w, x, y, z),
// T a translation. Moving transforms are interpolated in these parts, as
// Embree's quaternion motion blur interpolates them: S and T linearly, R
// along the great arc. Throws std::invalid_argument for a singular map.
struct TransformParts {
  std::array<std::array<double, 3>, 3> s{};
  std::array<double, 4> q{1, 0, 0, 0};
  std::array<double, 3> t{};

  static TransformParts of(const Transform& transform);
  Transform transform() const;
};

// Keys at evenly spaced times from 0 to 1 (the shutter's opening to its
// closing), their parts decomposed once; at(time) interpolates between the
// two keys around it. Consecutive rotations are taken the short way round.
class AnimatedTransform {
 public:
  AnimatedTransform() = default;
  explicit AnimatedTransform(const std::vector<Transform>& keys);

  Transform at(double time) const;
  const std::vector<TransformParts>& parts() const { return parts_; }
  // The number (from 2) of the first key whose scale or shear differs from
  // the first key's, or 0 when all share them: then the motion from the
  // first key's placement is rigid.
  size_t first_rescaled_key() const;

 private:
  std::vector<TransformParts> parts_;
};

}  // namespace caustica
