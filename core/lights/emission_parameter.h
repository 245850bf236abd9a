#pragma once

#include <string>

#include "core/math/color.h"
#include "core/registry/properties.h"

namespace caustica {

// An emitter's radiance or intensity: refused unless every channel is
// finite and non-negative (light does not take energy away).
Color read_emission(const Properties& props, const std::string& name);

}  // namespace caustica
