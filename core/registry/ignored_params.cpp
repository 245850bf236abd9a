#include "core/registry/ignored_params.h"

namespace caustica {

const std::vector<IgnoredParam>& ignored_params() {
  static const std::vector<IgnoredParam> params = {
      {"integrator",
       {"samples_per_pass", ParamType::Integer, std::nullopt, "accepted and ignored"},
       "the image does not depend on how its samples are split into passes"},
      {"integrator",
       {"block_size", ParamType::Integer, std::nullopt, "accepted and ignored"},
       "caustica chooses its own tiles; the image does not depend on them"},
      {"integrator",
       {"timeout", ParamType::Float, std::nullopt, "accepted and ignored (see --time)"},
       "caustica renders the sampler's sample count; give `caustica render --time SECONDS` to render by time"},
      {"emitter",
       {"sampling_weight", ParamType::Float, std::nullopt, "accepted and ignored"},
       "caustica chooses lights in proportion to their power; the image is the same, only its noise differs"},
      {"shape",
       {"silhouette_sampling_weight", ParamType::Float, std::nullopt, "accepted and ignored"},
       "it weighs silhouette sampling in differentiable rendering, which caustica does not do"},
  };
  return params;
}

const IgnoredParam* find_ignored_param(const std::string& category, const std::string& name) {
  for (const IgnoredParam& p : ignored_params())
    if (p.category == category && p.spec.name == name) return &p;
  return nullptr;
}

}  // namespace caustica
