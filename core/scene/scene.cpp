#include "core/scene/scene.h"

namespace caustica {

Scene::Scene(std::vector<std::shared_ptr<Shape>> shapes, std::vector<std::shared_ptr<Emitter>> emitters,
             std::shared_ptr<Sensor> sensor, std::string source)
    : shapes_(std::move(shapes)),
      emitters_(std::move(emitters)),
      sensor_(std::move(sensor)),
      source_(std::move(source)) {
  for (const auto& s : shapes_) bounds_.expand(s->bounds());
  for (const auto& e : emitters_) {
    e->prepare(bounds_);
    if (e->is_environment()) infinite_.push_back(e.get());
  }
  accel_ = std::make_unique<EmbreeScene>(shapes_);
  lights_ = std::make_unique<LightSelection>(emitters_);
}

uint64_t Scene::rays_traced() const {
  uint64_t total = 0;
  for (uint64_t n : rays_traced_) total += n;
  return total;
}

std::optional<SurfaceInteraction> Scene::first_shown(const Ray& ray, RayCounter& counter) const {
  Ray r = ray;
  float t_before = 0;
  for (;;) {
    ++counter.local();
    auto si = accel_->intersect(r);
    if (!si || !si->shape->is_null()) {
      if (si) si->t += t_before;
      return si;
    }
    t_before += si->t;
    r = si->spawn(r.d);
    r.t_max = ray.t_max - t_before;
  }
}

uint64_t Scene::layer_rays_traced() const {
  uint64_t total = 0;
  for (uint64_t n : layer_rays_traced_) total += n;
  return total;
}

}  // namespace caustica
