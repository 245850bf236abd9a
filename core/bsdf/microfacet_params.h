#pragma once

#include <memory>
#include <vector>

#include "core/bsdf/microfacet.h"
#include "core/registry/param_spec.h"
#include "core/texture/texture.h"

namespace caustica {

class Properties;

// The parameters of a rough material's microfacet distribution, as Mitsuba
// names them: `distribution` (beckmann or ggx), `alpha`, and with
// `anisotropic` the pair `alpha_u` / `alpha_v` instead; with `textured`,
// the roughness may be a texture.
std::vector<ParamSpec> microfacet_params(bool anisotropic, bool textured = false);

// The distribution those parameters describe; bad values are errors naming
// the parameter (a negative or non-finite roughness, alpha together with
// alpha_u / alpha_v, one of the pair alone, an unknown distribution).
MicrofacetDistribution microfacet_from(const Properties& props);

// A roughness that may vary over the surface: the distribution at a point
// has the textures' luminance there as alpha_u and alpha_v.
class MicrofacetRoughness {
 public:
  // From parameters declared with `textured`; checked as microfacet_from
  // checks them, a texture's whole range included.
  explicit MicrofacetRoughness(const Properties& props);
  MicrofacetDistribution at(Vec2 uv) const {
    const float u = alpha_u_->eval(uv).luminance();
    // An isotropic roughness (alpha, or the same texture twice) is read once.
    return {type_, u, alpha_v_ == alpha_u_ ? u : alpha_v_->eval(uv).luminance()};
  }
  MicrofacetDistribution::Type type() const { return type_; }
  // Bounds on every roughness the textures give.
  float lowest() const { return lowest_; }
  float highest() const { return highest_; }

 private:
  MicrofacetDistribution::Type type_;
  std::shared_ptr<Texture> alpha_u_, alpha_v_;
  float lowest_ = 0, highest_ = 0;
};

}  // namespace caustica
