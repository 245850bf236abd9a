// plastic: a diffuse base under a smooth dielectric coating, such as
// polished plastic or varnished wood.
//
// Light is either reflected by the coating as by a mirror, weighted by the
// Fresnel reflectance F, or refracted into it, scattered by the diffuse base
// and refracted out again. The base's light bounces between the base and the
// inside of the coating; F_dr, the coating's internal reflectance of diffuse
// light, sums those bounces:
//
//   f_spec = ks F(wo) delta(wi - mirror(wo)) / cos(theta_i)
//   f_diff = (1 - F(wo)) (1 - F(wi)) / eta^2  kd / (pi (1 - kd F_dr))   nonlinear
//                                            kd / (pi (1 - F_dr))       otherwise
//
// with eta = int_ior / ext_ior. The linear form keeps the colour of kd (as
// a painter expects); the nonlinear one saturates colours as real plastics
// do. With kd = ks = 1 both reflect all light. F_dr is integrated
// numerically from the Fresnel equations once per material.
//
// Sampling picks the mirror reflection with probability
//   F(wo) mean(ks) / (F(wo) mean(ks) + (1 - F(wo)) mean(kd)),
// the share of the reflected light each part carries (up to the base's
// internal bounces), and the cosine-weighted hemisphere otherwise. One-sided:
// nothing is reflected from below the normal.
//
//   <bsdf type="plastic">
//       <rgb name="diffuse_reflectance" value="0.1, 0.27, 0.36"/>
//       <float name="int_ior" value="1.9"/>
//   </bsdf>

#include <algorithm>
#include <cmath>

#include "core/bsdf/bsdf.h"
#include "core/bsdf/fresnel.h"
#include "core/bsdf/ior.h"
#include "core/bsdf/reflectance_at.h"
#include "core/math/constants.h"
#include "core/registry/properties.h"
#include "core/sampling/warp.h"
#include "core/texture/texture_parameter.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

Vec3 mirror(Vec3 w) { return {-w.x, -w.y, w.z}; }

class PlasticBsdf final : public Bsdf {
 public:
  explicit PlasticBsdf(const Properties& props)
      : kd_(read_reflectance(props, "diffuse_reflectance")),
        ks_(read_reflectance(props, "specular_reflectance")),
        eta_(read_ior(props, "int_ior") / read_ior(props, "ext_ior")),
        nonlinear_(props.get_bool("nonlinear")) {
    if (!(eta_ > 0) || !std::isfinite(eta_)) throw props.error("int_ior", "int_ior / ext_ior must be positive");
    fdr_ = internal_diffuse_reflectance(eta_);
  }

  uint32_t lobes() const override { return kDeltaReflection | kDiffuseReflection; }
  bool reads_tangents() const override { return false; }
  bool renders_spectral() const override { return true; }

  Color eval(const BsdfContext& ctx, Vec3 wo, Vec3 wi) const override {
    if (cos_theta(wo) <= 0 || cos_theta(wi) <= 0) return {};
    const float t = (1 - fresnel(wo)) * (1 - fresnel(wi)) / (eta_ * eta_);
    return base(reflectance_at(*kd_, ctx)) * (t * kInvPi);
  }

  float pdf(const BsdfContext& ctx, Vec3 wo, Vec3 wi) const override {
    if (cos_theta(wo) <= 0 || cos_theta(wi) <= 0) return 0;
    const float p_spec = specular_probability(ctx, fresnel(wo));
    if (!(p_spec >= 0)) return 0;
    return (1 - p_spec) * cosine_hemisphere_pdf(cos_theta(wi));
  }

  std::optional<BsdfSample> sample(const BsdfContext& ctx, Vec3 wo, float u_lobe, Vec2 u) const override {
    if (cos_theta(wo) <= 0) return std::nullopt;
    const float F = fresnel(wo);
    const float p_spec = specular_probability(ctx, F);
    if (!(p_spec >= 0)) return std::nullopt;  // black
    if (u_lobe < p_spec) {
      const Vec3 wi = mirror(wo);
      return BsdfSample{wi, reflectance_at(*ks_, ctx) * (F / cos_theta(wi)), p_spec, kDeltaReflection, 1};
    }
    const Vec3 wi = square_to_cosine_hemisphere(u);
    const float pdf_wi = (1 - p_spec) * cosine_hemisphere_pdf(cos_theta(wi));
    if (!(pdf_wi > 0)) return std::nullopt;
    return BsdfSample{wi, eval(ctx, wo, wi), pdf_wi, kDiffuseReflection, 1};
  }

  // Exact: the diffuse part reflects (1 - F(wo)) kd, times
  // (1 - F_dr) / (1 - kd F_dr) when nonlinear.
  Color albedo(const BsdfContext& ctx, Vec3 wo) const override {
    if (cos_theta(wo) <= 0) return {};
    const float F = fresnel(wo);
    return reflectance_at(*ks_, ctx) * F + base(reflectance_at(*kd_, ctx)) * ((1 - F) * (1 - fdr_));
  }

 private:
  float fresnel(Vec3 w) const { return fresnel_dielectric(cos_theta(w), eta_).F; }

  // kd with its internal bounces summed: kd / (1 - kd F_dr) or kd / (1 - F_dr).
  Color base(Color kd) const {
    const auto one = [&](float k) { return k / std::max(1 - (nonlinear_ ? k : 1.0f) * fdr_, 1e-6f); };
    return {one(kd.r), one(kd.g), one(kd.b)};
  }

  // NaN where the material is black.
  float specular_probability(const BsdfContext& ctx, float F) const {
    const float s = F * ks_->eval(ctx.uv).average(), d = (1 - F) * kd_->eval(ctx.uv).average();
    return s + d > 0 ? s / (s + d) : std::nanf("");
  }

  std::shared_ptr<Texture> kd_, ks_;
  float eta_;
  bool nonlinear_;
  float fdr_ = 0;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(
    PlasticBsdf, "bsdf", "plastic",
    {{"diffuse_reflectance", ParamType::Texture, "0.5", "kd, the reflectance of the diffuse base"},
     {"specular_reflectance", ParamType::Texture, "1", "ks, scales the coating's mirror reflection"},
     {"int_ior", ParamType::Ior, "polypropylene", "index of refraction of the coating (a number or a name)"},
     {"ext_ior", ParamType::Ior, "air", "index of refraction of the outside medium"},
     {"nonlinear", ParamType::Boolean, "false", "include the base's colour in internal bounces"}},
    {});

}  // namespace caustica
