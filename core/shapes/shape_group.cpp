#include "core/shapes/shape_group.h"

#include <algorithm>
#include <stdexcept>

#include "core/bsdf/bsdf.h"
#include "core/errors/scene_error.h"
#include "core/math/constants.h"
#include "core/registry/properties.h"
#include "core/shapes/rtc_scene.h"

namespace caustica {

ShapeGroup::ShapeGroup(const Properties& props) : shapes_(props.children<Shape>("shape")) {
  if (shapes_.empty()) throw SceneError(props.where(), "a shapegroup needs at least one shape");
  for (const auto& s : shapes_) {
    if (s->is_group() || s->is_instance())
      throw SceneError(props.where(), "a shapegroup cannot hold a shapegroup or an instance (one level of instancing)");
    if (s->emitter())
      throw SceneError(props.where(), "a shapegroup's shapes cannot emit (instances of area lights are not supported)");
    area_ += s->area();
    bounds_.expand(s->bounds());
  }
}

ShapeGroup::~ShapeGroup() {
  for (const auto& [device, scene] : built_) rtcReleaseScene(scene);
}

// Called while an EmbreeScene is built, on one thread, before any ray is
// traced; a device's scene, once built, is only read.
RTCScene ShapeGroup::rtc_scene(RTCDevice device) const {
  for (const auto& [d, scene] : built_)
    if (d == device) return scene;
  // Every device attaches the shapes in the same order, so the ids agree.
  RTCScene scene = build_rtc_scene(device, shapes_, by_geom_id_);
  built_.emplace_back(device, scene);
  return scene;
}

unsigned ShapeGroup::attach(RTCDevice, RTCScene) const {
  throw std::logic_error("a shapegroup is placed only by instances");
}

SurfaceInteraction ShapeGroup::interaction(const Ray&, const RayHit&) const {
  throw std::logic_error("a shapegroup is hit only through instances");
}

PositionSample ShapeGroup::sample_position(Vec2 u) const {
  if (!(area_ > 0)) return {};
  float target = u.x * area_;
  for (size_t i = 0; i < shapes_.size(); ++i) {
    const float a = shapes_[i]->area();
    if (target < a || i + 1 == shapes_.size()) {
      const Vec2 rescaled{std::min(a > 0 ? target / a : 0.0f, kOneMinusEpsilon), u.y};
      PositionSample ps = shapes_[i]->sample_position(rescaled);
      ps.pdf *= a / area_;
      return ps;
    }
    target -= a;
  }
  return {};
}

uint32_t ShapeGroup::lobes() const {
  uint32_t lobes = 0;
  for (const auto& s : shapes_) lobes |= s->lobes();
  return lobes;
}

CAUSTICA_REGISTER_PLUGIN(ShapeGroup, "shape", "shapegroup", {}, {"shape"});

}  // namespace caustica
