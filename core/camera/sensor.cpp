#include "core/camera/sensor.h"

#include "core/media/medium.h"
#include "core/registry/properties.h"
#include "core/registry/registry.h"

namespace caustica {

namespace {

template <class T>
std::shared_ptr<T> child_or_default(const Properties& props, const char* category, const char* name) {
  if (auto c = props.child<T>(category)) return c;
  return Registry::instance().create_default<T>(category, name, props.where());
}

}  // namespace

Sensor::Sensor(const Properties& props)
    : film_(child_or_default<Film>(props, "film", "hdrfilm")),
      sampler_(child_or_default<Sampler>(props, "sampler", "independent")),
      medium_(props.child<Medium>("medium")) {}

std::vector<ParamSpec> clip_params() {
  return {{"near_clip", ParamType::Float, "0.01", "near plane distance"},
          {"far_clip", ParamType::Float, "10000", "far plane distance"}};
}

}  // namespace caustica
