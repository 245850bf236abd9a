#pragma once

#include <memory>
#include <string>

#include "core/registry/properties.h"
#include "core/texture/texture.h"

namespace caustica {

// A parameter declared as a texture: the texture nested or referenced
// there, or a constant one for an rgb, spectrum or number.
std::shared_ptr<Texture> read_texture(const Properties& props, const std::string& name);

// A texture refused where negative or not finite, such as a radiance that
// varies over a surface (light does not take energy away).
std::shared_ptr<Texture> read_nonnegative_texture(const Properties& props, const std::string& name);

// A texture that is a reflectance or transmittance: a non-negative texture,
// accepted with a warning where above 1 (the surface then reflects more
// than it receives).
std::shared_ptr<Texture> read_reflectance(const Properties& props, const std::string& name);

// A texture that is a fraction, such as an opacity: refused outside [0, 1].
std::shared_ptr<Texture> read_fraction(const Properties& props, const std::string& name);

// A fraction texture's value at uv: its luminance clamped to [0, 1], or
// `fallback` where the texture holds no finite value there.
float eval_fraction(const Texture& texture, Vec2 uv, float fallback);

}  // namespace caustica
