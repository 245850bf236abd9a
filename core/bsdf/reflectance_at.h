#pragma once

#include "core/bsdf/bsdf.h"
#include "core/spectral/rgb_lift.h"
#include "core/texture/texture.h"

namespace caustica {

// A material's reflectance texture where the context asks: its RGB value,
// or in spectral mode its value at the path's wavelengths, lifted to a
// smooth spectrum within [0, 1].
inline Color reflectance_at(const Texture& texture, const BsdfContext& ctx) {
  const Color rgb = texture.eval(ctx.uv);
  return ctx.wavelengths ? lift_reflectance(rgb, *ctx.wavelengths) : rgb;
}

}  // namespace caustica
