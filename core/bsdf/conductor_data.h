#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/math/color.h"
#include "core/math/sampled_spectrum.h"
#include "core/registry/param_spec.h"

namespace caustica {

class Properties;

// Complex index of refraction eta + i k of a conductor, per RGB channel,
// relative to the medium outside it; where measured, also over wavelength
// (absolute, to be divided by `outside`), which spectral transport reads.
struct ConductorIor {
  Color eta, k;
  std::shared_ptr<const SampledSpectrum> eta_spectrum, k_spectrum;
  float outside = 1;
  // Whether eta and k are given over wavelength: by a metal's name (its
  // published measurements) or as spectra.
  bool measured() const { return eta_spectrum != nullptr; }
  // Given as spectra in the scene (rather than by a metal's name), which
  // the scene's analysis renders spectrally.
  bool scene_spectra = false;
};

// Measured metals by chemical symbol (Mitsuba's names): RGB values at about
// 650, 550 and 450 nm, and the published measurements over wavelength
// (core/spectral/metal_ior_tables.h).
std::optional<ConductorIor> named_conductor(const std::string& name);
std::vector<std::string> conductor_names();

// The index a conductor plugin was given: `material` names a metal, or is
// "none" and `eta` and `k` give the index (by default eta = 0, k = 1, a
// perfect mirror), as colours or as spectra (both, or neither, spectra).
// Giving both is an error, as is an unknown name.
ConductorIor conductor_ior(const Properties& props);
// The parameters conductor_ior reads: material, eta, k, and ext_eta (the
// outside's index, Mitsuba 0.x's extEta), which eta and k are relative to.
std::vector<ParamSpec> conductor_ior_params();

}  // namespace caustica
