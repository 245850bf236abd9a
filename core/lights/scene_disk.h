#pragma once

#include <algorithm>

#include "core/geometry/bounds.h"
#include "core/math/constants.h"
#include "core/math/frame.h"
#include "core/sampling/warp.h"

namespace caustica {

// Where light from an infinitely distant emitter (an environment or a
// directional light) enters the scene when traced from the light: a disk
// across the scene's bounding sphere, facing the direction of travel and
// outside the sphere, so that every point of the scene is reached.
class SceneDisk {
 public:
  void fit(const Bounds3& bounds) {
    if (bounds.empty()) return;
    center_ = bounds.center();
    radius_ = std::max(length(bounds.hi - center_), 1e-3f) * 1.01f;
  }

  // A point spread uniformly over the disk facing d (unit).
  Vec3 origin(Vec3 d, Vec2 u) const {
    const Frame frame = Frame::from_normal(d);
    const Vec2 disk = square_to_uniform_disk_concentric(u);
    return center_ - d * radius_ + (frame.s * disk.x + frame.t * disk.y) * radius_;
  }
  float area() const { return kPi * radius_ * radius_; }
  float pdf() const { return 1 / area(); }
  // Farther than any point of the scene from any other.
  float beyond() const { return 2 * radius_; }

 private:
  Vec3 center_;
  float radius_ = 1;
};

}  // namespace caustica
