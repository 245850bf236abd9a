#pragma once

#include <vector>

#include "core/bsdf/microfacet.h"
#include "core/registry/param_spec.h"

namespace caustica {

class Properties;

// The parameters of a rough material's microfacet distribution, as Mitsuba
// names them: `distribution` (beckmann or ggx), `alpha`, and with
// `anisotropic` the pair `alpha_u` / `alpha_v` instead.
std::vector<ParamSpec> microfacet_params(bool anisotropic);

// The distribution those parameters describe; bad values are errors naming
// the parameter (a negative or non-finite roughness, alpha together with
// alpha_u / alpha_v, one of the pair alone, an unknown distribution).
MicrofacetDistribution microfacet_from(const Properties& props);

}  // namespace caustica
