#pragma once

#include <memory>
#include <string>

#include "core/registry/properties.h"
#include "core/texture/texture.h"

namespace caustica {

// A parameter declared as a texture: the texture nested or referenced
// there, or a constant one for an rgb, spectrum or number.
std::shared_ptr<Texture> read_texture(const Properties& props, const std::string& name);

// A texture that is a reflectance or transmittance: refused where negative
// or not finite, accepted with a warning where above 1 (the surface then
// reflects more than it receives).
std::shared_ptr<Texture> read_reflectance(const Properties& props, const std::string& name);

// A texture that is a fraction, such as an opacity: refused outside [0, 1].
std::shared_ptr<Texture> read_fraction(const Properties& props, const std::string& name);

}  // namespace caustica
