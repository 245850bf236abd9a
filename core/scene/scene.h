#pragma once

#include <tbb/enumerable_thread_specific.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/camera/sensor.h"
#include "core/color/tone_operator.h"
#include "core/geometry/embree_scene.h"
#include "core/geometry/ray_log.h"
#include "core/lights/emitter.h"
#include "core/render/integrator.h"
#include "core/render/light_selection.h"
#include "core/scene/scene_features.h"
#include "core/shapes/shape.h"

namespace caustica {

// Everything a render needs, built by the scene loader.
class Scene {
 public:
  Scene(std::vector<std::shared_ptr<Shape>> shapes, std::vector<std::shared_ptr<Emitter>> emitters,
        std::shared_ptr<Sensor> sensor, std::shared_ptr<Integrator> integrator, std::string source);

  std::optional<SurfaceInteraction> intersect(const Ray& ray) const {
    ++rays_traced_.local();
    if (ray_log_) ray_log_->record(ray, false);
    return accel_->intersect(ray);
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
  // Rays traced so far, over all threads.
  uint64_t rays_traced() const;

  const std::vector<std::shared_ptr<Shape>>& shapes() const { return shapes_; }
  const std::vector<std::shared_ptr<Emitter>>& emitters() const { return emitters_; }
  const std::vector<const Emitter*>& infinite_emitters() const { return infinite_; }
  const LightSelection& light_selection() const { return *lights_; }
  const Sensor& sensor() const { return *sensor_; }
  const std::shared_ptr<Integrator>& integrator() const { return integrator_; }
  void set_integrator(std::shared_ptr<Integrator> integrator) { integrator_ = std::move(integrator); }
  // The scene's <tonemap>, or null: how its render is developed for display.
  const std::shared_ptr<ToneOperator>& tone_operator() const { return tone_operator_; }
  void set_tone_operator(std::shared_ptr<ToneOperator> op) { tone_operator_ = std::move(op); }
  const Bounds3& bounds() const { return bounds_; }
  // What the scene calls for (analyze_scene), set by the loader.
  const SceneFeatures& features() const { return features_; }
  void set_features(SceneFeatures features) { features_ = std::move(features); }
  const std::string& source() const { return source_; }

 private:
  std::vector<std::shared_ptr<Shape>> shapes_;
  std::vector<std::shared_ptr<Emitter>> emitters_;
  std::vector<const Emitter*> infinite_;
  std::shared_ptr<Sensor> sensor_;
  std::shared_ptr<Integrator> integrator_;
  std::shared_ptr<ToneOperator> tone_operator_;
  std::string source_;
  Bounds3 bounds_;
  SceneFeatures features_;
  std::unique_ptr<EmbreeScene> accel_;
  std::unique_ptr<LightSelection> lights_;
  mutable tbb::enumerable_thread_specific<uint64_t> rays_traced_{0};
  RayLog* ray_log_ = nullptr;
};

}  // namespace caustica
