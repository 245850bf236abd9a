#pragma once

#include <optional>
#include <string>

#include "core/camera/sensor.h"
#include "core/geometry/bounds.h"

namespace caustica {

// A warning when the camera's clip planes cut into the scene's bounds, else
// nothing. The defaults (Mitsuba's, 0.01 and 10000) are absolute lengths, so
// a scene modelled in other units can lose geometry to them unseen.
std::optional<std::string> clip_warning(const ClipPlanes& clip, const Bounds3& bounds);

}  // namespace caustica
