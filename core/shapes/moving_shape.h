#pragma once

#include <embree3/rtcore.h>

#include <memory>
#include <utility>
#include <vector>

#include "core/math/animated_transform.h"
#include "core/shapes/shape.h"

namespace caustica {

// A shape whose to_world moves over the shutter interval, written as
// Mitsuba 0.6 wrote it:
//
//   <shape type="sphere">
//       <animation name="to_world">
//           <transform time="0"><translate x="-1"/></transform>
//           <transform time="1"><translate x="1"/></transform>
//       </animation>
//   </shape>
//
// The shape is built in its own space and placed by an Embree instance
// with one time step per key (quaternion motion: scale and shear, rotation
// and translation interpolated apart, as AnimatedTransform does; a moving
// instance places its group's scene that way); a ray meets it where it is
// at the ray's time.
class MovingShape final : public Shape {
 public:
  // `keys` place the shape in render space, evenly spaced over the shutter
  // (the loader times them). Throws std::invalid_argument for a key that
  // cannot be decomposed.
  MovingShape(std::shared_ptr<Shape> local, const std::vector<Transform>& keys);
  ~MovingShape() override;
  MovingShape(const MovingShape&) = delete;
  MovingShape& operator=(const MovingShape&) = delete;

  bool moves() const override { return true; }
  unsigned attach(RTCDevice device, RTCScene scene) const override;
  SurfaceInteraction interaction(const Ray& ray, const RayHit& hit) const override;
  float area() const override { return local_->area(); }
  Bounds3 bounds() const override;
  PositionSample sample_position(Vec2 u) const override;
  uint32_t lobes() const override { return local_->lobes(); }
  std::vector<const Shape*> material_surfaces() const override { return local_->material_surfaces(); }
  std::string kind() const override { return local_->kind() + " (moving)"; }
  // The still shape's own test, where it stands at the hit's time.
  float boundary_test(const SurfaceInteraction& si, Vec3 d) const override;

 private:
  std::shared_ptr<Shape> local_;
  AnimatedTransform motion_;
  mutable std::vector<std::pair<RTCDevice, RTCScene>> built_;
  mutable std::vector<const Shape*> by_geom_id_;
};

}  // namespace caustica
