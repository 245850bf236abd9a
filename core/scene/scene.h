#pragma once

#include <tbb/enumerable_thread_specific.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/camera/sensor.h"
#include "core/geometry/ray_log.h"
#include "core/lights/emitter.h"
#include "core/lights/light_selection.h"
#include "core/math/transform.h"
#include "core/scene/embree_scene.h"
#include "core/scene/scene_features.h"
#include "core/shapes/shape.h"

namespace caustica {

// What a scene file describes to be rendered: shapes, emitters, the sensor
// with its film and sampler, and what the scene analysis found. How it is
// rendered (the integrator, the tone mapping) is the render job's business.
class Scene {
 public:
  Scene(std::vector<std::shared_ptr<Shape>> shapes, std::vector<std::shared_ptr<Emitter>> emitters,
        std::shared_ptr<Sensor> sensor, std::string source);

  std::optional<SurfaceInteraction> intersect(const Ray& ray) const {
    ++rays_traced_.local();
    if (ray_log_) ray_log_->record(ray, false);
    return accel_->intersect(ray);
  }
  // The first surface `ray` shows before ray.t_max: null surfaces (the
  // boundaries of media) show nothing and are looked through, and media are
  // not shown either; t stays the ray parameter along `ray`.
  std::optional<SurfaceInteraction> intersect_shown(const Ray& ray) const { return first_shown(ray, rays_traced_); }
  // The same query for the first-hit layers, which re-trace a camera ray
  // the integrator traces too: counted apart, so that the rays reported for
  // a render are the integrator's, each once.
  std::optional<SurfaceInteraction> intersect_for_layers(const Ray& ray) const {
    return first_shown(ray, layer_rays_traced_);
  }
  bool occluded(const Ray& ray) const {
    ++rays_traced_.local();
    if (ray_log_) ray_log_->record(ray, true);
    return accel_->occluded(ray);
  }
  // Records every ray traced from now on into `log` (null to stop); for
  // benchmarks that replay a render's rays.
  void set_ray_log(RayLog* log) { ray_log_ = log; }
  // The acceleration structure itself, for benchmarks that query Embree directly.
  const EmbreeScene& accel() const { return *accel_; }
  // Rays traced so far, over all threads: by intersect() and occluded(),
  // and by intersect_for_layers().
  uint64_t rays_traced() const;
  uint64_t layer_rays_traced() const;

  const std::vector<std::shared_ptr<Shape>>& shapes() const { return shapes_; }
  const std::vector<std::shared_ptr<Emitter>>& emitters() const { return emitters_; }
  // The environments a ray leaving the scene can meet (a directional
  // light, a delta in direction, is met by none).
  const std::vector<const Emitter*>& infinite_emitters() const { return infinite_; }
  const LightSelection& light_selection() const { return *lights_; }
  const Sensor& sensor() const { return *sensor_; }
  const Bounds3& bounds() const { return bounds_; }
  // What the scene calls for (analyze_scene), set by the loader.
  const SceneFeatures& features() const { return features_; }
  void set_features(SceneFeatures features) { features_ = std::move(features); }
  // The world-space point that is the origin of the space the scene is
  // stored and rendered in (the camera's position).
  Vec3d render_origin() const { return render_origin_; }
  Vec3 render_point(Vec3d world) const {
    return {float(world.x - render_origin_.x), float(world.y - render_origin_.y), float(world.z - render_origin_.z)};
  }
  Vec3d world_point(Vec3 render) const {
    return {render.x + render_origin_.x, render.y + render_origin_.y, render.z + render_origin_.z};
  }
  void set_render_origin(Vec3d origin) { render_origin_ = origin; }
  const std::string& source() const { return source_; }

 private:
  std::vector<std::shared_ptr<Shape>> shapes_;
  std::vector<std::shared_ptr<Emitter>> emitters_;
  std::vector<const Emitter*> infinite_;
  std::shared_ptr<Sensor> sensor_;
  std::string source_;
  Bounds3 bounds_;
  SceneFeatures features_;
  Vec3d render_origin_;
  std::unique_ptr<EmbreeScene> accel_;
  std::unique_ptr<LightSelection> lights_;
  // Each thread finds its counter through a native thread-local key: the
  // default lookup hashes the thread's id, which cost 2 % of a path render.
  using RayCounter =
      tbb::enumerable_thread_specific<uint64_t, tbb::cache_aligned_allocator<uint64_t>, tbb::ets_key_per_instance>;
  mutable RayCounter rays_traced_{0}, layer_rays_traced_{0};
  std::optional<SurfaceInteraction> first_shown(const Ray& ray, RayCounter& counter) const;
  RayLog* ray_log_ = nullptr;
};

}  // namespace caustica
