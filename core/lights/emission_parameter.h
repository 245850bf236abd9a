#pragma once

#include <memory>
#include <string>

#include "core/math/color.h"
#include "core/registry/properties.h"
#include "core/texture/texture.h"

namespace caustica {

// An emitter's radiance or intensity: refused unless every channel is
// finite and non-negative (light does not take energy away).
Color read_emission(const Properties& props, const std::string& name);

// The same for a radiance that may vary over a surface: a texture whose
// every value is finite and non-negative.
std::shared_ptr<Texture> read_emission_texture(const Properties& props, const std::string& name);

}  // namespace caustica
