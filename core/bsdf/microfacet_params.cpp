#include "core/bsdf/microfacet_params.h"

#include <cmath>
#include <stdexcept>

#include "core/registry/properties.h"

namespace caustica {

std::vector<ParamSpec> microfacet_params(bool anisotropic) {
  std::vector<ParamSpec> params = {{"distribution", ParamType::String, "beckmann", "beckmann or ggx"},
                                   {"alpha", ParamType::Float, "0.1", "roughness"}};
  if (anisotropic) {
    params.push_back({"alpha_u", ParamType::Float, std::nullopt, "roughness along the tangent, with alpha_v"});
    params.push_back({"alpha_v", ParamType::Float, std::nullopt, "roughness along the bitangent, with alpha_u"});
  }
  return params;
}

MicrofacetDistribution microfacet_from(const Properties& props) {
  MicrofacetDistribution::Type type;
  try {
    type = MicrofacetDistribution::parse_type(props.get_string("distribution"));
  } catch (const std::invalid_argument& e) {
    throw props.error("distribution", e.what());
  }
  const bool has_u = props.has("alpha_u"), has_v = props.has("alpha_v");
  if (props.has("alpha") && (has_u || has_v))
    throw props.error("alpha", "give either alpha or alpha_u and alpha_v, not both");
  if (has_u != has_v) throw props.error(has_u ? "alpha_u" : "alpha_v", "alpha_u and alpha_v go together");
  const auto roughness = [&](const char* name) {
    const char* source = props.has(name) ? name : "alpha";
    const float alpha = props.get_float(source);
    if (!(alpha >= 0) || !std::isfinite(alpha)) throw props.error(source, "roughness must be finite and not negative");
    return alpha;
  };
  return {type, roughness("alpha_u"), roughness("alpha_v")};
}

}  // namespace caustica
