#pragma once

#include <optional>
#include <string>

#include "core/geometry/bounds.h"

namespace caustica {

// What is wrong with shapes bounded by `render_bounds` (in render space)
// for tracing them (see traceable_size.h), or nothing; empty bounds (no
// shapes) are fine.
std::optional<std::string> scene_extent_problem(const Bounds3& render_bounds);

}  // namespace caustica
