#pragma once

#include <embree3/rtcore.h>

#include <memory>
#include <optional>
#include <vector>

#include "core/shapes/shape.h"

namespace caustica {

// A caustica ray as Embree takes it (all geometry masks, no flags).
RTCRay to_rtc(const Ray& ray);

// Ray queries over the scene's shapes through Embree.
class EmbreeScene {
 public:
  explicit EmbreeScene(const std::vector<std::shared_ptr<Shape>>& shapes);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  std::optional<SurfaceInteraction> intersect(const Ray& ray) const;
  // Whether anything blocks the ray before t_max.
  bool occluded(const Ray& ray) const;
  // The shape of Embree geometry `geom` at the top of the scene (an
  // interaction's shape_index).
  const Shape& shape(unsigned geom) const { return *by_geom_id_[geom]; }
  // Embree's scene, for benchmarks that measure Embree alone on the same geometry.
  RTCScene rtc_scene() const { return scene_; }

 private:
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  std::vector<const Shape*> by_geom_id_;
};

}  // namespace caustica
