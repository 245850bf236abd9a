#pragma once

#include "core/bsdf/bsdf.h"
#include "core/bsdf/conductor_data.h"
#include "core/bsdf/fresnel.h"
#include "core/spectral/rgb_lift.h"
#include "core/texture/texture.h"

namespace caustica {

// A material's values where the context asks: in RGB, or in spectral mode
// at the path's wavelengths.

// A reflectance (or transmittance) texture, lifted to a smooth spectrum
// within [0, 1] in spectral mode.
inline Color reflectance_at(const Texture& texture, const BsdfContext& ctx) {
  const Color rgb = texture.eval(ctx.uv);
  return ctx.wavelengths ? lift_reflectance(rgb, *ctx.wavelengths) : rgb;
}

// A conductor's Fresnel reflectance; in spectral mode its eta and k are
// lifted as values that may exceed 1 (a smooth spectrum through the RGB
// table values, not the metal's measured spectrum).
inline Color fresnel_conductor_at(const BsdfContext& ctx, float cos_i, const ConductorIor& ior) {
  if (!ctx.wavelengths) return fresnel_conductor(cos_i, ior.eta, ior.k);
  return fresnel_conductor(cos_i, lift_unbounded(ior.eta, *ctx.wavelengths), lift_unbounded(ior.k, *ctx.wavelengths));
}

}  // namespace caustica
