#pragma once

#include <memory>
#include <vector>

#include "core/lights/emitter.h"
#include "core/math/rigid_motion.h"

namespace caustica {

// A light that moves over the shutter: a light whose to_world is an
// <animation name="to_world">, or the area light of a moving shape.
// `still` is the light where `placement` puts it (a point or spot light's
// first key; for an area light, its shape's own space, where the shape is
// built with the keys' shared scale); at a time, the light is carried
// rigidly from there to where the interpolated keys put it, and what it
// sends toward a point, or emits along a ray, is the still light's,
// carried: a rigid map keeps distances and angles, so radiance,
// intensities and densities keep too. A directional or environment light
// is infinitely far: it only turns, by its keys' rotations, about the
// scene's centre (where its light paths enter the scene), and its keys'
// translations move nothing.
class MovingEmitter final : public Emitter {
 public:
  // `keys` are in render space, evenly spaced over the shutter. Throws
  // std::invalid_argument for keys whose scales or shears differ.
  MovingEmitter(std::shared_ptr<Emitter> still, const std::vector<Transform>& keys, const Transform& placement);

  void prepare(const Bounds3& bounds) override;
  bool is_area() const override { return still_->is_area(); }
  std::optional<LiSample> sample_Li(const ReferencePoint& ref, Vec2 u) const override;
  float pdf_Li(const ReferencePoint& ref, Vec3 wi, const SurfaceInteraction& on_light) const override;
  // A hit on the moving shape is where the shape is at the ray's time:
  // radiance depends only on the angle to its normal and on its (u, v).
  Color L(const SurfaceInteraction& si, Vec3 w) const override { return still_->L(si, w); }
  Color Le_infinite(Vec3 d, float time) const override;
  std::optional<LeSample> sample_Le(Vec2 u_pos, Vec2 u_dir, float time) const override;
  void pdf_Le(const Ray& ray, Vec3 n, float* pdf_pos, float* pdf_dir) const override;
  Color power() const override { return still_->power(); }
  bool is_delta() const override { return still_->is_delta(); }
  bool is_infinite() const override { return still_->is_infinite(); }
  bool moves() const override { return true; }

 private:
  // The rigid map from the still light to the light at `time`.
  Transform at(float time) const;

  std::shared_ptr<Emitter> still_;
  RigidMotion motion_;
  Vec3 pivot_;  // the scene's centre, for an infinitely far light
};

}  // namespace caustica
