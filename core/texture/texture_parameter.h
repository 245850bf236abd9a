#pragma once

#include <memory>
#include <string>

#include "core/registry/properties.h"
#include "core/texture/texture.h"

namespace caustica {

// A parameter declared as a texture: the texture nested or referenced
// there, or a constant one for an rgb, spectrum or number.
std::shared_ptr<Texture> read_texture(const Properties& props, const std::string& name);

}  // namespace caustica
