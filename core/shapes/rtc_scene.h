#pragma once

#include <embree3/rtcore.h>

#include <memory>
#include <vector>

#include "core/shapes/shape.h"

namespace caustica {

// A committed Embree scene holding the shapes, and in `by_geom_id` the shape
// behind each geometry id. Robust mode makes the triangle test watertight
// and conservative, which the floating-point error bounds of the hit points
// rely on; the render scene and every shape group are built alike.
RTCScene build_rtc_scene(RTCDevice device, const std::vector<std::shared_ptr<Shape>>& shapes,
                         std::vector<const Shape*>& by_geom_id);

}  // namespace caustica
