// phong: the energy-conserving, physically plausible Phong model (Lafortune
// and Willems, "Using the modified Phong reflectance model for physically
// based rendering", 1994):
//
//   f(wo, wi) = kd / pi + ks (n + 2) / (2 pi) cos^n(alpha)
//
// where alpha is the angle between wi and the mirror direction of wo. The
// model is reciprocal, and reflects at most kd + ks of the light arriving
// from any direction (the part of the cos^n lobe below the horizon is lost),
// so kd + ks must not exceed 1 in any channel.
//
// kd + ks is checked against 1 on the textures' means (exactly, for
// constant values); above 1 both are scaled down by the largest sum, with a
// warning, as Mitsuba 0.x does (or, with ensure_energy_conservation false,
// the material is refused). Sampling picks the glossy lobe with probability
// mean(ks) / (mean(kd) + mean(ks)) at the shading point, then samples cos^n
// around the mirror direction or the cosine-weighted hemisphere; pdf() is
// the mixture. One-sided: nothing is reflected from below the normal.
//
//   <bsdf type="phong">
//       <rgb name="diffuse_reflectance" value="0.4, 0.2, 0.1"/>
//       <rgb name="specular_reflectance" value="0.3"/>
//       <float name="exponent" value="80"/>
//   </bsdf>

#include <algorithm>
#include <cmath>

#include "core/bsdf/bsdf.h"
#include "core/bsdf/reflectance_at.h"
#include "core/math/constants.h"
#include "core/registry/properties.h"
#include "core/sampling/warp.h"
#include "core/texture/scaled_texture.h"
#include "core/texture/texture_parameter.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// The mirror direction of w about the normal +z.
Vec3 mirror(Vec3 w) { return {-w.x, -w.y, w.z}; }

class PhongBsdf final : public Bsdf {
 public:
  explicit PhongBsdf(const Properties& props)
      : kd_(read_reflectance(props, "diffuse_reflectance")),
        ks_(read_reflectance(props, "specular_reflectance")),
        exponent_(props.get_float("exponent")) {
    if (!(exponent_ >= 0) || !std::isfinite(exponent_))
      throw props.error("exponent", "must be a finite number of 0 or more");
    const Color sum = kd_->mean() + ks_->mean();
    const float most = std::max({sum.r, sum.g, sum.b});
    if (!(most > 1)) return;
    const int c = sum.r == most ? 0 : sum.g == most ? 1 : 2;
    const std::string what =
        "diffuse_reflectance + specular_reflectance is " + std::to_string(most) + " in channel " + std::to_string(c);
    if (!props.get_bool("ensure_energy_conservation"))
      throw props.error("specular_reflectance", what + "; it must be at most 1 to conserve energy");
    // As Mitsuba 0.x: both scaled down, with a warning.
    kd_ = std::make_shared<ScaledTexture>(kd_, 1 / most);
    ks_ = std::make_shared<ScaledTexture>(ks_, 1 / most);
    props.warn("specular_reflectance", what + "; both are scaled by " + std::to_string(1 / most) +
                                           " to conserve energy (ensure_energy_conservation)");
  }

  uint32_t lobes() const override { return kDiffuseReflection | kGlossyReflection; }
  bool reads_tangents() const override { return false; }
  bool renders_spectral() const override { return true; }

  Color eval(const BsdfContext& ctx, Vec3 wo, Vec3 wi) const override {
    if (cos_theta(wo) <= 0 || cos_theta(wi) <= 0) return {};
    Color f = reflectance_at(*kd_, ctx) * kInvPi;
    const float cos_alpha = dot(wi, mirror(wo));
    if (cos_alpha > 0) f += reflectance_at(*ks_, ctx) * ((exponent_ + 2) * kInv2Pi * std::pow(cos_alpha, exponent_));
    return f;
  }

  float pdf(const BsdfContext& ctx, Vec3 wo, Vec3 wi) const override {
    if (cos_theta(wo) <= 0 || cos_theta(wi) <= 0) return 0;
    const float p_glossy = glossy_probability(ctx);
    if (!(p_glossy >= 0)) return 0;
    const float cos_alpha = dot(wi, mirror(wo));
    const float glossy = cos_alpha > 0 ? (exponent_ + 1) * kInv2Pi * std::pow(cos_alpha, exponent_) : 0.0f;
    return p_glossy * glossy + (1 - p_glossy) * cosine_hemisphere_pdf(cos_theta(wi));
  }

  std::optional<BsdfSample> sample(const BsdfContext& ctx, Vec3 wo, float u_lobe, Vec2 u) const override {
    if (cos_theta(wo) <= 0) return std::nullopt;
    const float p_glossy = glossy_probability(ctx);
    if (!(p_glossy >= 0)) return std::nullopt;  // kd = ks = 0
    Vec3 wi;
    if (u_lobe < p_glossy) {
      // cos(alpha) = u^(1 / (n + 1)); 1 - cos(alpha) through expm1 keeps the
      // lobe's width accurate for huge exponents.
      const float log_u = std::log(std::max(u.x, 1e-30f)) / (exponent_ + 1);
      const float cos_alpha = std::exp(log_u), one_minus = -std::expm1(log_u);
      const float sin_alpha = std::sqrt(std::max(0.0f, one_minus * (1 + cos_alpha)));
      const float phi = 2 * kPi * u.y;
      const Frame frame = Frame::from_normal(mirror(wo));
      wi = frame.to_world({sin_alpha * std::cos(phi), sin_alpha * std::sin(phi), cos_alpha});
    } else {
      wi = square_to_cosine_hemisphere(u);
    }
    // The glossy lobe reaches below the horizon: such samples carry nothing.
    if (cos_theta(wi) <= 0) return std::nullopt;
    const float pdf_wi = pdf(ctx, wo, wi);
    if (!(pdf_wi > 0)) return std::nullopt;
    const uint32_t lobe = u_lobe < p_glossy ? kGlossyReflection : kDiffuseReflection;
    return BsdfSample{wi, eval(ctx, wo, wi), pdf_wi, lobe, 1};
  }

  // kd plus ks times the glossy lobe's reflectance for a lobe lying wholly
  // above the horizon, cos(theta_o) (exact at normal incidence, a close
  // lower bound for narrow lobes elsewhere).
  Color albedo(const BsdfContext& ctx, Vec3 wo) const override {
    if (cos_theta(wo) <= 0) return {};
    return reflectance_at(*kd_, ctx) + reflectance_at(*ks_, ctx) * cos_theta(wo);
  }

 private:
  // NaN where both parts are black.
  float glossy_probability(const BsdfContext& ctx) const {
    const float d = kd_->eval(ctx.uv).average(), s = ks_->eval(ctx.uv).average();
    return d + s > 0 ? s / (d + s) : std::nanf("");
  }

  std::shared_ptr<Texture> kd_, ks_;
  float exponent_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(PhongBsdf, "bsdf", "phong",
                         {{"diffuse_reflectance", ParamType::Texture, "0.5", "diffuse reflectance kd"},
                          {"specular_reflectance", ParamType::Texture, "0.2", "glossy reflectance ks"},
                          {"exponent", ParamType::Float, "30", "Phong exponent n, the lobe's sharpness (0 or more)"},
                          {"ensure_energy_conservation", ParamType::Boolean, "true",
                           "scale both reflectances down, with a warning, where they sum above 1 (else refuse)"}},
                         {});

}  // namespace caustica
