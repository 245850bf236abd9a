#pragma once

#include <memory>
#include <vector>

#include "core/lights/emitter.h"
#include "core/math/animated_transform.h"

namespace caustica {

// A point or spot light whose to_world moves over the shutter, written as a
// moving shape's is (an <animation name="to_world"> in the <emitter>).
// `still` is the light placed by the first key; at a time, the light is
// carried rigidly from there to where the interpolated keys put it, and
// what it sends toward a point, or emits along a ray, is the still light's,
// carried: a rigid map keeps distances and angles, so intensities and
// densities keep too.
class MovingEmitter final : public Emitter {
 public:
  // `keys` are in render space, evenly spaced over the shutter, the first
  // the still light's to_world. Throws std::invalid_argument for a light
  // that is not a point or a spot, or keys whose scales or shears differ.
  MovingEmitter(std::shared_ptr<Emitter> still, const std::vector<Transform>& keys);

  void prepare(const Bounds3& bounds) override { still_->prepare(bounds); }
  std::optional<LiSample> sample_Li(const ReferencePoint& ref, Vec2 u) const override;
  // Zero, as for every delta light (no direction sampled otherwise reaches it).
  float pdf_Li(const ReferencePoint&, Vec3, const SurfaceInteraction&) const override { return 0; }
  std::optional<LeSample> sample_Le(Vec2 u_pos, Vec2 u_dir, float time) const override;
  void pdf_Le(const Ray& ray, Vec3 n, float* pdf_pos, float* pdf_dir) const override;
  Color power() const override { return still_->power(); }
  bool is_delta() const override { return true; }
  bool moves() const override { return true; }

 private:
  // The rigid map from the first key's placement to the one at `time`.
  Transform carried(float time) const;

  std::shared_ptr<Emitter> still_;
  AnimatedTransform motion_;
  Transform first_inverse_;
};

}  // namespace caustica
