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
// material). So light lost to masking is not lost to the material, which
// keeps a white material white at every roughness. The diffuse part is
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
// square slope of the facets for beckmann).
//
//   <bsdf type="roughplastic">
//       <string name="distribution" value="ggx"/>
//       <float name="alpha" value="0.3"/>
//       <rgb name="diffuse_reflectance" value="0.1, 0.27, 0.36"/>
//   </bsdf>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "core/bsdf/bsdf.h"
#include "core/bsdf/fresnel.h"
#include "core/bsdf/ior.h"
#include "core/bsdf/microfacet_params.h"
#include "core/math/constants.h"
#include "core/registry/properties.h"
#include "core/sampling/warp.h"
#include "core/texture/texture_parameter.h"

namespace caustica {
namespace {

class RoughPlasticBsdf final : public Bsdf {
 public:
  explicit RoughPlasticBsdf(const Properties& props)
      : dist_(microfacet_from(props)),
        kd_(read_reflectance(props, "diffuse_reflectance")),
        ks_(read_reflectance(props, "specular_reflectance")),
        eta_(read_ior(props, "int_ior") / read_ior(props, "ext_ior")),
        nonlinear_(props.get_bool("nonlinear")) {
    if (!(eta_ > 0) || !std::isfinite(eta_)) throw props.error("int_ior", "int_ior / ext_ior must be positive");
    fdr_ = internal_diffuse_reflectance(eta_);
    tabulate_albedo();
  }

  uint32_t lobes() const override { return kGlossyReflection | kDiffuseReflection; }

  Color eval(const BsdfContext& ctx, Vec3 wo, Vec3 wi) const override {
    if (cos_theta(wo) <= 0 || cos_theta(wi) <= 0) return {};
    const float diffuse = (1 - fdr_) * (1 - coating_albedo(cos_theta(wo))) * (1 - coating_albedo(cos_theta(wi))) /
                          (kPi * (1 - mean_albedo_));
    return base(kd_->eval(ctx.uv)) * diffuse + ks_->eval(ctx.uv) * specular(wo, wi);
  }

  float pdf(const BsdfContext& ctx, Vec3 wo, Vec3 wi) const override {
    if (cos_theta(wo) <= 0 || cos_theta(wi) <= 0) return 0;
    const float p_spec = specular_probability(ctx, wo);
    if (!(p_spec >= 0)) return 0;
    const Vec3 m = normalize(wo + wi);
    const float spec = p_spec > 0 ? dist_.pdf(wo, m) / (4 * dot(wo, m)) : 0.0f;
    return p_spec * spec + (1 - p_spec) * cosine_hemisphere_pdf(cos_theta(wi));
  }

  std::optional<BsdfSample> sample(const BsdfContext& ctx, Vec3 wo, float u_lobe, Vec2 u) const override {
    if (cos_theta(wo) <= 0) return std::nullopt;
    const float p_spec = specular_probability(ctx, wo);
    if (!(p_spec >= 0)) return std::nullopt;  // black
    Vec3 wi;
    uint32_t lobe;
    if (u_lobe < p_spec) {
      const Vec3 m = dist_.sample(wo, u);
      if (!(dot(wo, m) > 0)) return std::nullopt;
      wi = reflect(wo, m);
      lobe = kGlossyReflection;
    } else {
      wi = square_to_cosine_hemisphere(u);
      lobe = kDiffuseReflection;
    }
    if (!(cos_theta(wi) > 0)) return std::nullopt;
    const float pdf_wi = pdf(ctx, wo, wi);
    if (!(pdf_wi > 0) || !std::isfinite(pdf_wi)) return std::nullopt;
    return BsdfSample{wi, eval(ctx, wo, wi), pdf_wi, lobe, 1};
  }

  // Exact up to the tabulation of E.
  Color albedo(const BsdfContext& ctx, Vec3 wo) const override {
    if (cos_theta(wo) <= 0) return {};
    const float e = coating_albedo(cos_theta(wo));
    return ks_->eval(ctx.uv) * e + base(kd_->eval(ctx.uv)) * ((1 - fdr_) * (1 - e));
  }

 private:
  // Nodes at cos(theta) = (i / (kTableSize - 1))^2, dense near grazing where E changes fastest.
  static constexpr int kTableSize = 64;
  static constexpr int kStrata = 64;  // per axis, for each node's integral

  float specular(Vec3 wo, Vec3 wi) const {
    const Vec3 m = normalize(wo + wi);
    const float F = fresnel_dielectric(dot(wo, m), eta_).F;
    return F * dist_.D(m) * dist_.G(wo, wi, m) / (4 * cos_theta(wo) * cos_theta(wi));
  }

  // E(mu) = int f_spec cos(theta_i) dwi for ks = 1, by stratified sampling
  // of microfacet normals: with dwi = 4 (wo.m) dm the integrand over m is
  // F D G (wo.m) / cos(theta_o), divided by the density of sample(). The
  // table's mean 2 int E mu dmu is exact for the piecewise linear E.
  void tabulate_albedo() {
    for (int i = 0; i < kTableSize; ++i) {
      const float mu = std::max(node(i), 1e-4f);
      const Vec3 wo(std::sqrt(std::max(0.0f, 1 - mu * mu)), 0, mu);
      double sum = 0;
      for (int a = 0; a < kStrata; ++a)
        for (int b = 0; b < kStrata; ++b) {
          const Vec3 m = dist_.sample(wo, {(a + 0.5f) / kStrata, (b + 0.5f) / kStrata});
          const float wo_m = dot(wo, m), density = dist_.pdf(wo, m);
          if (!(wo_m > 0) || !(density > 0)) continue;
          const Vec3 wi = reflect(wo, m);
          if (!(wi.z > 0)) continue;
          const double value =
              double(fresnel_dielectric(wo_m, eta_).F) * dist_.D(m) * dist_.G(wo, wi, m) * wo_m / (mu * density);
          if (std::isfinite(value)) sum += value;
        }
      table_[i] = float(std::clamp(sum / (kStrata * kStrata), 0.0, 1.0));
    }
    double mean = 0;
    for (int i = 0; i + 1 < kTableSize; ++i) {
      const double a = node(i), b = node(i + 1);
      mean += (b - a) / 6 * (table_[i] * (2 * a + b) + table_[i + 1] * (a + 2 * b));
    }
    mean_albedo_ = float(std::min(2 * mean, 1 - 1e-6));
  }

  static float node(int i) {
    const float x = float(i) / (kTableSize - 1);
    return x * x;
  }

  // E at cos(theta) = mu, interpolated linearly in mu.
  float coating_albedo(float mu) const {
    const float x = std::sqrt(std::clamp(mu, 0.0f, 1.0f)) * (kTableSize - 1);
    const int i = std::min(int(x), kTableSize - 2);
    const float t = std::clamp((mu - node(i)) / (node(i + 1) - node(i)), 0.0f, 1.0f);
    return table_[i] * (1 - t) + table_[i + 1] * t;
  }

  // kd with its internal bounces summed: kd / (1 - kd F_dr) or kd / (1 - F_dr).
  Color base(Color kd) const {
    const auto one = [&](float k) { return k / std::max(1 - (nonlinear_ ? k : 1.0f) * fdr_, 1e-6f); };
    return {one(kd.r), one(kd.g), one(kd.b)};
  }

  // NaN where the material is black.
  float specular_probability(const BsdfContext& ctx, Vec3 wo) const {
    const float e = coating_albedo(cos_theta(wo));
    const float s = e * ks_->eval(ctx.uv).average(), d = (1 - e) * kd_->eval(ctx.uv).average();
    return s + d > 0 ? s / (s + d) : std::nanf("");
  }

  MicrofacetDistribution dist_;
  std::shared_ptr<Texture> kd_, ks_;
  float eta_;
  bool nonlinear_;
  float fdr_ = 0;
  std::array<float, kTableSize> table_{};
  float mean_albedo_ = 0;
};

std::vector<ParamSpec> params() {
  auto p = microfacet_params(false);
  p.insert(p.end(),
           {{"diffuse_reflectance", ParamType::Texture, "0.5", "kd, the reflectance of the diffuse base"},
            {"specular_reflectance", ParamType::Texture, "1", "ks, scales the coating's reflection"},
            {"int_ior", ParamType::Ior, "polypropylene", "index of refraction of the coating (a number or a name)"},
            {"ext_ior", ParamType::Ior, "air", "index of refraction of the outside medium"},
            {"nonlinear", ParamType::Boolean, "false", "include the base's colour in internal bounces"}});
  return p;
}

}  // namespace

CAUSTICA_REGISTER_PLUGIN(RoughPlasticBsdf, "bsdf", "roughplastic", params(), {});

}  // namespace caustica
