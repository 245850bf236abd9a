// roughconductor: a rough metal, microfacet reflection (Torrance-Sparrow)
// with the Fresnel reflectance of a conductor,
//   f = F(wo.m) D(m) G(wo, wi, m) / (4 cos(wo) cos(wi)),  m the half vector,
// with a Beckmann or GGX distribution of normals and Smith's
// height-correlated masking-shadowing. Light scattered more than once
// between the facets is lost, so rough surfaces come out a little dark.
//
// Give either `material` or `eta` and `k`; with the defaults (eta 0, k 1)
// the Fresnel reflectance is 1 at every angle. One-sided: light arriving
// from below the shading normal is not reflected.
//
// `distribution` is beckmann or ggx; alpha is the roughness (the root mean
// square slope of the facets for beckmann). alpha_u and alpha_v make it
// anisotropic, along the tangent and the bitangent: give both or neither,
// and not together with alpha; without them both are alpha.
//
//   <bsdf type="roughconductor">
//       <string name="material" value="Al"/>
//       <string name="distribution" value="ggx"/>
//       <float name="alpha_u" value="0.05"/>
//       <float name="alpha_v" value="0.3"/>
//   </bsdf>

#include <cmath>
#include <stdexcept>

#include "core/bsdf/bsdf.h"
#include "core/bsdf/conductor_data.h"
#include "core/bsdf/fresnel.h"
#include "core/bsdf/microfacet_params.h"
#include "core/bsdf/reflectance_at.h"
#include "core/registry/properties.h"
#include "core/texture/texture_parameter.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// The normal reflecting wo into wi, both above the surface; +z where the
// two are opposite grazing directions.
Vec3 half_vector(Vec3 wo, Vec3 wi) {
  const Vec3 h = wo + wi;
  const float len = length(h);
  return len > 0 ? h / len : Vec3(0, 0, 1);
}

class RoughConductorBsdf final : public Bsdf {
 public:
  explicit RoughConductorBsdf(const Properties& props)
      : roughness_(props),
        ior_(conductor_ior(props)),
        specular_reflectance_(read_reflectance(props, "specular_reflectance")),
        sample_visible_(props.get_bool("sample_visible")) {}

  uint32_t lobes() const override { return kGlossyReflection; }
  bool reads_tangents() const override { return false; }
  bool renders_spectral() const override { return true; }

  Color eval(const BsdfContext& ctx, Vec3 wo, Vec3 wi) const override {
    return eval_with(roughness_.at(ctx.uv), ctx, wo, wi);
  }

  float pdf(const BsdfContext& ctx, Vec3 wo, Vec3 wi) const override { return pdf_with(roughness_.at(ctx.uv), wo, wi); }

  std::optional<BsdfSample> sample(const BsdfContext& ctx, Vec3 wo, float, Vec2 u) const override {
    if (!(cos_theta(wo) > 0)) return std::nullopt;
    const MicrofacetDistribution distribution = roughness_.at(ctx.uv);
    const Vec3 m = sample_visible_ ? distribution.sample(wo, u) : distribution.sample_D(u);
    const float wo_m = dot(wo, m);
    if (!(wo_m > 0)) return std::nullopt;
    const Vec3 wi = reflect(wo, m);
    if (!(cos_theta(wi) > 0)) return std::nullopt;
    // The pdf of the half vector of the pair, as pdf() computes it, so that
    // the sample agrees with pdf() to rounding.
    const float pdf = pdf_with(distribution, wo, wi);
    if (!(pdf > 0)) return std::nullopt;
    return BsdfSample{wi, eval_with(distribution, ctx, wo, wi), pdf, kGlossyReflection, 1};
  }

  // Fresnel reflectance at the macro-surface normal: an approximation that
  // ignores the energy lost between facets, close for low roughness.
  Color albedo(const BsdfContext& ctx, Vec3 wo) const override {
    if (!(cos_theta(wo) > 0)) return {};
    return fresnel_conductor_at(ctx, cos_theta(wo), ior_) * reflectance_at(*specular_reflectance_, ctx);
  }

 private:
  // eval and pdf with the distribution at the point, found once per call.
  Color eval_with(const MicrofacetDistribution& d, const BsdfContext& ctx, Vec3 wo, Vec3 wi) const {
    if (!(cos_theta(wo) > 0 && cos_theta(wi) > 0)) return {};
    const Vec3 m = half_vector(wo, wi);
    const float D = d.D(m);
    if (D == 0) return {};
    const float G = d.G(wo, wi, m);
    const Color F = fresnel_conductor_at(ctx, dot(wo, m), ior_) * reflectance_at(*specular_reflectance_, ctx);
    return F * (D * G / (4 * cos_theta(wo) * cos_theta(wi)));
  }
  float pdf_with(const MicrofacetDistribution& d, Vec3 wo, Vec3 wi) const {
    if (!(cos_theta(wo) > 0 && cos_theta(wi) > 0)) return 0;
    const Vec3 m = half_vector(wo, wi);
    const float wo_m = dot(wo, m);
    if (!(wo_m > 0)) return 0;
    return (sample_visible_ ? d.pdf(wo, m) : d.pdf_D(m)) / (4 * wo_m);
  }

  MicrofacetRoughness roughness_;
  ConductorIor ior_;
  std::shared_ptr<Texture> specular_reflectance_;
  bool sample_visible_;
};

std::vector<ParamSpec> params() {
  auto p = microfacet_params(true, true);
  const auto ior = conductor_ior_params();
  p.insert(p.end(), ior.begin(), ior.end());
  p.insert(p.end(), {{"specular_reflectance", ParamType::Texture, "1", "factor on the reflectance (not physical)"},
                     {"sample_visible", ParamType::Boolean, "true", "sample only the facet normals visible from wo"}});
  return p;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(RoughConductorBsdf, "bsdf", "roughconductor", CAUSTICA_UNITY_ID::params(), {});

}  // namespace caustica
