#pragma once

#include <optional>

#include "core/math/transform.h"

namespace caustica {

// The scale of a transform that only translates, rotates (or mirrors) and
// scales uniformly, to a relative tolerance of 1e-4; none for any other.
// Spheres and cylinders stay round only under these.
std::optional<float> similarity_scale(const Transform& t);

}  // namespace caustica
