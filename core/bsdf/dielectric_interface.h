#pragma once

#include <memory>
#include <optional>

#include "core/bsdf/bsdf.h"
#include "core/registry/param_spec.h"
#include "core/spectral/dispersion.h"
#include "core/texture/texture.h"

namespace caustica {

class Properties;

// What every dielectric material reads from its parameters: the relative
// index of refraction int_ior / ext_ior and the textures that scale the
// reflected and the transmitted light. With `dispersion` the inside's index
// varies with wavelength: in spectral mode a bounce refracts by the index at
// the path's hero wavelength, in RGB mode by the one at the helium d line.
struct DielectricInterface {
  // A thin sheet, whose transmitted light does not change direction, takes
  // no dispersion (reads_dispersion false).
  explicit DielectricInterface(const Properties& props, bool reads_dispersion = true);

  // The relative index where the context asks.
  float eta_at(const BsdfContext& ctx) const {
    if (!dispersion || !ctx.wavelengths) return eta;
    return float(dispersion->ior(ctx.wavelengths->nm[0]) / ext_ior);
  }
  bool disperses() const { return dispersion.has_value(); }

  float eta;  // at the d line where the inside disperses
  float ext_ior;
  std::optional<Dispersion> dispersion;
  std::shared_ptr<Texture> reflectance, transmittance;
};

// The `dispersion` parameter the materials above declare.
ParamSpec dispersion_param();

}  // namespace caustica
