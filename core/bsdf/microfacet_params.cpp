#include "core/bsdf/microfacet_params.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "core/registry/properties.h"
#include "core/texture/texture_parameter.h"

namespace caustica {

std::vector<ParamSpec> microfacet_params(bool anisotropic, bool textured) {
  const ParamType type = textured ? ParamType::Texture : ParamType::Float;
  std::vector<ParamSpec> params = {
      {"distribution", ParamType::String, "beckmann", "beckmann or ggx"},
      {"alpha", type, "0.1", textured ? "roughness (a number or a texture)" : "roughness"}};
  if (anisotropic) {
    params.push_back({"alpha_u", type, std::nullopt, "roughness along the tangent, with alpha_v"});
    params.push_back({"alpha_v", type, std::nullopt, "roughness along the bitangent, with alpha_u"});
  }
  return params;
}

namespace {
namespace CAUSTICA_UNITY_ID {

MicrofacetDistribution::Type distribution_type(const Properties& props) {
  try {
    return MicrofacetDistribution::parse_type(props.get_string("distribution"));
  } catch (const std::invalid_argument& e) {
    throw props.error("distribution", e.what());
  }
}

void check_pairing(const Properties& props) {
  const bool has_u = props.has("alpha_u"), has_v = props.has("alpha_v");
  if (props.has("alpha") && (has_u || has_v))
    throw props.error("alpha", "give either alpha or alpha_u and alpha_v, not both");
  if (has_u != has_v) throw props.error(has_u ? "alpha_u" : "alpha_v", "alpha_u and alpha_v go together");
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

MicrofacetRoughness::MicrofacetRoughness(const Properties& props) : type_(distribution_type(props)) {
  check_pairing(props);
  const auto roughness = [&](const char* name) {
    const char* source = props.has(name) ? name : "alpha";
    auto texture = read_texture(props, source);
    const ValueRange range = texture->range();
    if (!(range.lowest >= 0) || !std::isfinite(range.highest))
      throw props.error(source, "roughness must be finite and not negative");
    return std::pair{texture, range};
  };
  const auto [u, u_range] = roughness("alpha_u");
  // Without alpha_u / alpha_v both directions share alpha's one texture.
  const auto [v, v_range] = props.has("alpha_v") ? roughness("alpha_v") : std::pair{u, u_range};
  alpha_u_ = u;
  alpha_v_ = v;
  lowest_ = std::min(u_range.lowest, v_range.lowest);
  highest_ = std::max(u_range.highest, v_range.highest);
}

MicrofacetDistribution microfacet_from(const Properties& props) {
  const MicrofacetDistribution::Type type = distribution_type(props);
  check_pairing(props);
  const auto roughness = [&](const char* name) {
    const char* source = props.has(name) ? name : "alpha";
    const float alpha = props.get_float(source);
    if (!(alpha >= 0) || !std::isfinite(alpha)) throw props.error(source, "roughness must be finite and not negative");
    return alpha;
  };
  return {type, roughness("alpha_u"), roughness("alpha_v")};
}

}  // namespace caustica
