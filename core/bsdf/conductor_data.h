#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/math/color.h"
#include "core/registry/param_spec.h"

namespace caustica {

class Properties;

// Complex index of refraction eta + i k of a conductor, per RGB channel,
// relative to the medium outside it.
struct ConductorIor {
  Color eta, k;
};

// Measured metals by chemical symbol (Mitsuba's names), as RGB values at
// about 650, 550 and 450 nm.
std::optional<ConductorIor> named_conductor(const std::string& name);
std::vector<std::string> conductor_names();

// The index a conductor plugin was given: `material` names a metal, or is
// "none" and `eta` and `k` give the index (by default eta = 0, k = 1, a
// perfect mirror). Giving both is an error, as is an unknown name.
ConductorIor conductor_ior(const Properties& props);
// The parameters conductor_ior reads: material, eta, k, and ext_eta (the
// outside's index, Mitsuba 0.x's extEta), which eta and k are relative to.
std::vector<ParamSpec> conductor_ior_params();

}  // namespace caustica
