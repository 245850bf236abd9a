#include "core/camera/sensor.h"

#include <cmath>

#include "core/media/medium.h"
#include "core/registry/properties.h"
#include "core/registry/registry.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

template <class T>
std::shared_ptr<T> child_or_default(const Properties& props, const char* category, const char* name) {
  if (auto c = props.child<T>(category)) return c;
  return Registry::instance().create_default<T>(category, name, props.where());
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

Sensor::Sensor(const Properties& props)
    : film_(child_or_default<Film>(props, "film", "hdrfilm")),
      sampler_(child_or_default<Sampler>(props, "sampler", "independent")),
      medium_(props.child<Medium>("medium")),
      shutter_open_(props.get_float("shutter_open")),
      shutter_close_(props.get_float("shutter_close")) {
  if (!std::isfinite(shutter_open_)) throw props.error("shutter_open", "must be finite");
  if (!std::isfinite(shutter_close_) || shutter_close_ < shutter_open_)
    throw props.error("shutter_close", "must be finite and no earlier than shutter_open");
}

std::vector<ParamSpec> sensor_params() {
  return {{"near_clip", ParamType::Float, "0.01", "near plane distance"},
          {"far_clip", ParamType::Float, "10000", "far plane distance"},
          {"shutter_open", ParamType::Float, "0",
           "time the shutter opens (moving shapes' and cameras' keys span the shutter)"},
          {"shutter_close", ParamType::Float, "0", "time the shutter closes"}};
}

}  // namespace caustica
