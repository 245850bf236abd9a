#pragma once

#include <memory>
#include <vector>

#include "core/camera/sensor.h"
#include "core/math/rigid_motion.h"

namespace caustica {

// A camera whose to_world moves over the shutter, written as a moving
// shape's is (an <animation name="to_world"> in the <sensor>). `still` is
// the camera placed by the first key; at a time, the camera is carried
// rigidly from there to where the interpolated keys put it. Its rays, its
// importance and the connections light paths make to its lens are the
// still camera's, carried: lengths and angles keep, so do importance and
// densities.
class MovingSensor final : public Sensor {
 public:
  // `keys` are in render space, evenly spaced over the shutter, the first
  // the still camera's to_world. Throws std::invalid_argument if their
  // scales or shears differ (a camera moves and turns; an orthographic
  // camera's scale is the size of its view and stays).
  MovingSensor(std::shared_ptr<Sensor> still, const std::vector<Transform>& keys);

  Ray generate_ray(Vec2 raster, Vec2 u_lens, float time) const override;
  bool has_lens() const override { return still_->has_lens(); }
  bool delta_direction() const override { return still_->delta_direction(); }
  Color We(const Ray& ray, Vec2* raster) const override;
  void pdf_We(const Ray& ray, float* pdf_pos, float* pdf_dir) const override;
  std::optional<WiSample> sample_Wi(const ReferencePoint& ref, Vec2 u) const override;
  // Where the camera stands as the shutter opens.
  ClipPlanes clip_planes() const override { return still_->clip_planes(); }
  bool moves() const override { return true; }

 private:
  // `ray` as the still camera sees it.
  Ray to_still(const Ray& ray) const;

  std::shared_ptr<Sensor> still_;
  RigidMotion motion_;  // from the first key's placement
};

}  // namespace caustica
