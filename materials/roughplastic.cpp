// roughplastic: a diffuse base under a rough dielectric coating (`plastic`
// with a microfacet interface), such as matte or brushed plastic.
//
// The coating reflects as a microfacet surface,
//
//   f_spec = ks F(wo.m) D(m) G(wo, wi, m) / (4 cos(theta_o) cos(theta_i)),  m = normalize(wo + wi),
//
// with Smith's height-correlated G. Light the coating does not reflect is
// taken to reach the diffuse base: where `plastic` transmits 1 - F(cos),
// this model transmits 1 - E(cos), E being the coating's directional albedo
// (f_spec's reflectance for ks = 1, tabulated over cos(theta) once per
// material, and over the range of a roughness texture). So light lost to
// masking is not lost to the material, which keeps a white material white
// at every roughness. The diffuse part is
// plastic's, with 1/eta^2 written as (1 - F_dr) / (1 - F_dr,ext) and the
// external diffuse reflectance F_dr,ext replaced by E's cosine-weighted mean
// E_avg:
//
//   f_diff = kd' (1 - F_dr) (1 - E(wo)) (1 - E(wi)) / (pi (1 - E_avg))
//   kd' = kd / (1 - kd F_dr)  nonlinear,   kd / (1 - F_dr)  otherwise
//
// with F_dr the smooth coating's internal diffuse reflectance. As alpha goes
// to 0 this becomes `plastic`. This is an approximation (the base's light
// leaving through a rough interface is not traced), but it is reciprocal
// and reflects exactly ks E(wo) + kd' (1 - F_dr) (1 - E(wo)), at most 1.
//
// Sampling reflects wo about a microfacet normal drawn from the
// distribution (its visible normals for ggx) with probability
//   E(wo) mean(ks) / (E(wo) mean(ks) + (1 - E(wo)) mean(kd)),
// and samples the cosine-weighted hemisphere otherwise; pdf() is the
// mixture. One-sided: nothing is reflected from below the normal.
//
// `distribution` is beckmann or ggx; alpha is the roughness (the root mean
// square slope of the facets for beckmann), a number or a texture.
//
//   <bsdf type="roughplastic">
//       <string name="distribution" value="ggx"/>
//       <float name="alpha" value="0.3"/>
//       <rgb name="diffuse_reflectance" value="0.1, 0.27, 0.36"/>
//   </bsdf>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/bsdf/bsdf.h"
#include "core/bsdf/coating_albedo.h"
#include "core/bsdf/fresnel.h"
#include "core/bsdf/ior.h"
#include "core/bsdf/microfacet_params.h"
#include "core/bsdf/reflectance_at.h"
#include "core/math/constants.h"
#include "core/registry/properties.h"
#include "core/sampling/warp.h"
#include "core/texture/texture_parameter.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class RoughPlasticBsdf final : public Bsdf {
 public:
  explicit RoughPlasticBsdf(const Properties& props)
      : roughness_(props),
        kd_(read_reflectance(props, "diffuse_reflectance")),
        ks_(read_reflectance(props, "specular_reflectance")),
        eta_(checked_eta(props)),
        nonlinear_(props.get_bool("nonlinear")),
        sample_visible_(props.get_bool("sample_visible")),
        coating_(roughness_.type(), roughness_.lowest(), roughness_.highest(), eta_) {
    fdr_ = internal_diffuse_reflectance(eta_);
  }

  uint32_t lobes() const override { return kGlossyReflection | kDiffuseReflection; }
  bool reads_tangents() const override { return false; }
  bool renders_spectral() const override { return true; }

  Color eval(const BsdfContext& ctx, Vec3 wo, Vec3 wi) const override {
    if (cos_theta(wo) <= 0 || cos_theta(wi) <= 0) return {};
    return eval_with(at(ctx, wo), wo, wi);
  }

  float pdf(const BsdfContext& ctx, Vec3 wo, Vec3 wi) const override {
    if (cos_theta(wo) <= 0 || cos_theta(wi) <= 0) return 0;
    return pdf_with(at(ctx, wo), wo, wi);
  }

  std::optional<BsdfSample> sample(const BsdfContext& ctx, Vec3 wo, float u_lobe, Vec2 u) const override {
    if (cos_theta(wo) <= 0) return std::nullopt;
    const ShadingPoint p = at(ctx, wo);
    if (!(p.p_spec >= 0)) return std::nullopt;  // black
    Vec3 wi;
    uint32_t lobe;
    if (u_lobe < p.p_spec) {
      const Vec3 m = sample_visible_ ? p.dist.sample(wo, u) : p.dist.sample_D(u);
      if (!(dot(wo, m) > 0)) return std::nullopt;
      wi = reflect(wo, m);
      lobe = kGlossyReflection;
    } else {
      wi = square_to_cosine_hemisphere(u);
      lobe = kDiffuseReflection;
    }
    if (!(cos_theta(wi) > 0)) return std::nullopt;
    const float pdf_wi = pdf_with(p, wo, wi);
    if (!(pdf_wi > 0) || !std::isfinite(pdf_wi)) return std::nullopt;
    return BsdfSample{wi, eval_with(p, wo, wi), pdf_wi, lobe, 1};
  }

  // Exact up to the tabulation of E.
  Color albedo(const BsdfContext& ctx, Vec3 wo) const override {
    if (cos_theta(wo) <= 0) return {};
    const ShadingPoint p = at(ctx, wo);
    return p.ks * p.e_o + base(p.kd) * ((1 - fdr_) * (1 - p.e_o));
  }

 private:
  // Checked before the coating's tables are built from it.
  static float checked_eta(const Properties& props) {
    const float eta = read_ior(props, "int_ior") / read_ior(props, "ext_ior");
    if (!(eta > 0) || !std::isfinite(eta)) throw props.error("int_ior", "int_ior / ext_ior must be positive");
    return eta;
  }

  // What the textures and the coating's table give at a shading point seen
  // from wo, read once per call: eval, pdf and sample all need them.
  struct ShadingPoint {
    MicrofacetDistribution dist;
    Color kd, ks;
    float e_o;     // the coating's albedo E(cos theta_o)
    float p_spec;  // the glossy lobe's sampling probability; NaN where the material is black
  };

  ShadingPoint at(const BsdfContext& ctx, Vec3 wo) const {
    const MicrofacetDistribution dist = roughness_.at(ctx.uv);
    const Color kd = reflectance_at(*kd_, ctx), ks = reflectance_at(*ks_, ctx);
    const float e_o = coating_(dist.alpha_u(), cos_theta(wo));
    const float s = e_o * ks.average(), d = (1 - e_o) * kd.average();
    return {dist, kd, ks, e_o, s + d > 0 ? s / (s + d) : std::nanf("")};
  }

  Color eval_with(const ShadingPoint& p, Vec3 wo, Vec3 wi) const {
    const float alpha = p.dist.alpha_u();
    const float diffuse =
        (1 - fdr_) * (1 - p.e_o) * (1 - coating_(alpha, cos_theta(wi))) / (kPi * (1 - coating_.mean(alpha)));
    return base(p.kd) * diffuse + p.ks * specular(p.dist, wo, wi);
  }

  float pdf_with(const ShadingPoint& p, Vec3 wo, Vec3 wi) const {
    if (!(p.p_spec >= 0)) return 0;
    const Vec3 m = normalize(wo + wi);
    const float spec = p.p_spec > 0 ? (sample_visible_ ? p.dist.pdf(wo, m) : p.dist.pdf_D(m)) / (4 * dot(wo, m)) : 0.0f;
    return p.p_spec * spec + (1 - p.p_spec) * cosine_hemisphere_pdf(cos_theta(wi));
  }

  float specular(const MicrofacetDistribution& dist, Vec3 wo, Vec3 wi) const {
    const Vec3 m = normalize(wo + wi);
    const float F = fresnel_dielectric(dot(wo, m), eta_).F;
    return F * dist.D(m) * dist.G(wo, wi, m) / (4 * cos_theta(wo) * cos_theta(wi));
  }

  // kd with its internal bounces summed: kd / (1 - kd F_dr) or kd / (1 - F_dr).
  Color base(Color kd) const {
    const auto one = [&](float k) { return k / std::max(1 - (nonlinear_ ? k : 1.0f) * fdr_, 1e-6f); };
    return {one(kd.r), one(kd.g), one(kd.b)};
  }

  MicrofacetRoughness roughness_;
  std::shared_ptr<Texture> kd_, ks_;
  float eta_;
  bool nonlinear_;
  bool sample_visible_;
  CoatingAlbedo coating_;
  float fdr_ = 0;
};

std::vector<ParamSpec> params() {
  auto p = microfacet_params(false, true);
  p.insert(p.end(),
           {{"diffuse_reflectance", ParamType::Texture, "0.5", "kd, the reflectance of the diffuse base"},
            {"specular_reflectance", ParamType::Texture, "1", "ks, scales the coating's reflection"},
            {"int_ior", ParamType::Ior, "polypropylene", "index of refraction of the coating (a number or a name)"},
            {"ext_ior", ParamType::Ior, "air", "index of refraction of the outside medium"},
            {"nonlinear", ParamType::Boolean, "false", "include the base's colour in internal bounces"},
            {"sample_visible", ParamType::Boolean, "true", "sample only the facet normals visible from wo"}});
  return p;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(RoughPlasticBsdf, "bsdf", "roughplastic", CAUSTICA_UNITY_ID::params(), {});

}  // namespace caustica
