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
// within [0, 1] in spectral mode; one given as a measured spectrum is read
// at the wavelengths, within [0, 1].
inline Color reflectance_at(const Texture& texture, const BsdfContext& ctx) {
  if (!ctx.wavelengths) return texture.eval(ctx.uv);
  if (const SampledSpectrum* s = texture.spectrum()) return spectrum_at(*s, *ctx.wavelengths).clamp(0, 1);
  return lift_reflectance(texture.eval(ctx.uv), *ctx.wavelengths);
}

// A conductor's Fresnel reflectance; in spectral mode its measured eta and
// k at the wavelengths, or where it has none, eta and k lifted as values
// that may exceed 1.
inline Color fresnel_conductor_at(const BsdfContext& ctx, float cos_i, const ConductorIor& ior) {
  if (!ctx.wavelengths) return fresnel_conductor(cos_i, ior.eta, ior.k);
  if (ior.measured())
    return fresnel_conductor(cos_i, spectrum_at(*ior.eta_spectrum, *ctx.wavelengths) / ior.outside,
                             spectrum_at(*ior.k_spectrum, *ctx.wavelengths) / ior.outside);
  return fresnel_conductor(cos_i, lift_unbounded(ior.eta, *ctx.wavelengths), lift_unbounded(ior.k, *ctx.wavelengths));
}

}  // namespace caustica
