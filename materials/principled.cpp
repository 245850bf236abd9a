// principled: Burley's principled material (the Disney BRDF of 2012, made a
// BSDF in 2015), as Mitsuba 3 names its parameters; the Blender exporter's
// usual output. One artist-friendly set of numbers in [0, 1] blends a
// diffuse base, a metal, rough glass, sheen and a clearcoat. With
// brdf = (1 - metallic)(1 - spec_trans) and bsdf = (1 - metallic) spec_trans,
// seen from outside (wo above the surface) it is the sum of
//
//   diffuse    brdf base / pi  burley_diffuse(...)        (principled_lobes.h)
//   sheen      brdf sheen  lerp(1, base / lum(base), sheen_tint)  (1 - cos_d)^5
//   specular   F D G / (4 cos_o cos_i)
//   glass      bsdf sqrt(base) (1 - F_d) D G |wo.m wi.m| s / (cos_o cos_i (wo.m + eta wi.m)^2)
//   clearcoat  clearcoat / 4  F_c D_c G_c / (4 cos_o cos_i)
//
// with D and G anisotropic GGX (alpha from roughness^2, stretched by
// anisotropic) and Smith's separable masking, as in the 2012 notes; s as in
// `roughdielectric` (1 for radiance, eta^2 for importance). The specular
// Fresnel blends the dielectric's exact reflectance F_d with Schlick's:
//   F = (1 - metallic)(1 - spec_tint) F_d + metallic S(base)
//       + (1 - metallic) spec_tint S(base / lum(base) R0(eta)).
// The clearcoat has F_c = S(0.04), D_c Burley's GTR1 with alpha from 0.1 to
// 0.001 as clearcoat_gloss goes from 0 to 1, G_c Smith's GGX at alpha 0.25.
// From inside (wo below, which only glass reaches) it is rough glass
// weighted by bsdf: F_d reflected, sqrt(base) (1 - F_d) transmitted, so
// light crossing in and out takes the base colour once.
//
// Where caustica departs from Mitsuba 3: sheen is weighted by brdf (Mitsuba
// weights it by 1 - metallic wherever brdf > 0, so it jumps as spec_trans
// reaches 1), and the clearcoat keeps the 1 / (4 cos_o cos_i) of the notes.
// The material is not energy-conserving (nor meant to be): Burley's diffuse
// reflects up to about 1.2 at roughness 1.
//
// Sampling chooses the diffuse lobe (cosine-weighted, also covering sheen),
// the clearcoat (GTR1 normals) or the specular lobes (GGX visible normals,
// then reflection with probability 1 - bsdf (1 - F_d) and refraction
// otherwise) in proportion to brdf, clearcoat / 4 and 1, each times its
// sampling rate.
//
//   <bsdf type="principled">
//       <rgb name="base_color" value="0.8, 0.3, 0.2"/>
//       <float name="roughness" value="0.3"/>
//       <float name="clearcoat" value="0.5"/>
//   </bsdf>

#include <algorithm>
#include <cmath>

#include "core/bsdf/bsdf.h"
#include "core/bsdf/fresnel.h"
#include "core/bsdf/microfacet.h"
#include "core/bsdf/principled_lobes.h"
#include "core/math/constants.h"
#include "core/registry/properties.h"
#include "core/sampling/warp.h"
#include "core/texture/texture.h"
#include "core/texture/texture_parameter.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class PrincipledBsdf final : public Bsdf {
 public:
  explicit PrincipledBsdf(const Properties& props)
      : base_color_(read_reflectance(props, "base_color")),
        roughness_(read_fraction(props, "roughness")),
        anisotropic_(read_fraction(props, "anisotropic")),
        metallic_(read_fraction(props, "metallic")),
        spec_trans_(read_fraction(props, "spec_trans")),
        spec_tint_(read_fraction(props, "spec_tint")),
        sheen_(read_fraction(props, "sheen")),
        sheen_tint_(read_fraction(props, "sheen_tint")),
        flatness_(read_fraction(props, "flatness")),
        clearcoat_(read_fraction(props, "clearcoat")),
        clearcoat_gloss_(read_fraction(props, "clearcoat_gloss")),
        eta_(read_eta(props)),
        rate_diffuse_(read_sampling_rate(props, "diffuse_reflectance_sampling_rate")),
        rate_specular_(read_sampling_rate(props, "main_specular_sampling_rate")),
        rate_clearcoat_(read_sampling_rate(props, "clearcoat_sampling_rate")),
        transmits_(spec_trans_->range().highest > 0 && metallic_->range().lowest < 1) {}

  uint32_t lobes() const override {
    return kDiffuseReflection | kGlossyReflection | (transmits_ ? kGlossyTransmission : 0u);
  }

  Color eval(const BsdfContext& ctx, Vec3 wo, Vec3 wi) const override {
    if (wo.z == 0 || wi.z == 0) return {};
    return evaluate(at(ctx), ctx.mode, wo, wi).f;
  }

  float pdf(const BsdfContext& ctx, Vec3 wo, Vec3 wi) const override {
    if (wo.z == 0 || wi.z == 0) return 0;
    return evaluate(at(ctx), ctx.mode, wo, wi).pdf;
  }

  std::optional<BsdfSample> sample(const BsdfContext& ctx, Vec3 wo, float u_lobe, Vec2 u) const override {
    if (wo.z == 0) return std::nullopt;
    const Inputs p = at(ctx);
    if (wo.z < 0 && !(p.bsdf > 0)) return std::nullopt;
    const Choice c = choice(p, wo.z > 0);
    Vec3 wi;
    uint32_t lobe = kGlossyReflection;
    float eta = 1;
    if (u_lobe < c.diffuse) {
      wi = square_to_cosine_hemisphere(u);
      lobe = kDiffuseReflection;
    } else if (u_lobe < c.diffuse + c.clearcoat) {
      const Vec3 m = Gtr1{p.clearcoat_alpha}.sample(u);
      if (!(dot(wo, m) > 0)) return std::nullopt;
      wi = reflect(wo, m);
    } else {
      const Vec3 m = p.dist.sample(wo.z > 0 ? wo : -wo, u);
      const float wo_m = dot(wo, m);
      if (wo_m * wo.z <= 0) return std::nullopt;
      const DielectricFresnel fr = fresnel_dielectric(wo_m, eta_);
      // The rest of u_lobe, rescaled, chooses reflection or refraction.
      const float u_reflect = (u_lobe - c.diffuse - c.clearcoat) / c.specular;
      if (u_reflect < reflect_probability(p, wo.z > 0, fr.F)) {
        wi = reflect(wo, m);
      } else {
        if (fr.F >= 1) return std::nullopt;
        wi = refract(wo, m, fr.cos_t, fr.eta_ti);
        lobe = kGlossyTransmission;
        eta = fr.eta_it;
      }
    }
    if (wi.z == 0 || (lobe == kGlossyTransmission) != (wi.z * wo.z < 0)) return std::nullopt;
    const Evaluation e = evaluate(p, ctx.mode, wo, wi);
    if (!(e.pdf > 0) || !std::isfinite(e.pdf) || !e.f.is_finite()) return std::nullopt;
    return BsdfSample{wi, e.f, e.pdf, lobe, eta};
  }

  // An estimate for the albedo AOV: the diffuse base and the glass's
  // transmission behind the dielectric's Fresnel at wo, plus the specular
  // Fresnel, as for smooth surfaces.
  Color albedo(const BsdfContext& ctx, Vec3 wo) const override {
    if (wo.z == 0) return {};
    const Inputs p = at(ctx);
    const float F = fresnel_dielectric(wo.z, eta_).F;
    if (wo.z < 0) return Color(p.bsdf * F) + sqrt_color(p.base) * (p.bsdf * (1 - F));
    return p.base * (p.brdf * (1 - F)) + sqrt_color(p.base) * (p.bsdf * (1 - F)) + specular_fresnel(p, wo.z, F);
  }

 private:
  // The textures' values at a shading point, and what follows from them.
  struct Inputs {
    Color base;
    float roughness, metallic, spec_tint, sheen, sheen_tint, flatness, clearcoat;
    float brdf, bsdf;  // the weights of the opaque base and of the glass
    MicrofacetDistribution dist{MicrofacetDistribution::Type::GGX, 1, 1};
    float clearcoat_alpha;
  };

  // The probabilities of choosing each group of lobes.
  struct Choice {
    float diffuse, clearcoat, specular;
  };

  struct Evaluation {
    Color f;
    float pdf = 0;
  };

  static float read_eta(const Properties& props) {
    if (props.has("eta") && props.has("specular"))
      throw props.error("specular", "give either eta or specular, not both (each sets the other)");
    if (props.has("eta")) {
      const float eta = props.get_float("eta");
      if (!(eta > 0) || !std::isfinite(eta)) throw props.error("eta", "must be positive");
      // Glass of index 1 would be invisible, which the lobes below do not
      // model; Mitsuba makes it 1.001 too.
      return eta == 1 ? 1.001f : eta;
    }
    const float specular = props.get_float("specular");
    // specular = R0 / 0.08, and R0 = 1 would need an infinite index; 0
    // (index 1) is taken as 0.001, as the glass's facets need an interface.
    if (!(specular >= 0 && specular < 12.5f)) throw props.error("specular", "must lie in [0, 12.5)");
    const float s = std::sqrt(0.08f * std::max(specular, 1e-3f));
    return 2 / (1 - s) - 1;
  }

  static Color sqrt_color(Color c) { return {std::sqrt(c.r), std::sqrt(c.g), std::sqrt(c.b)}; }

  Inputs at(const BsdfContext& ctx) const {
    const Vec2 uv = ctx.uv;
    Inputs p;
    p.base = base_color_->eval(uv);
    p.roughness = eval_fraction(*roughness_, uv, 0.5f);
    p.metallic = eval_fraction(*metallic_, uv, 0);
    p.spec_tint = eval_fraction(*spec_tint_, uv, 0);
    p.sheen = eval_fraction(*sheen_, uv, 0);
    p.sheen_tint = eval_fraction(*sheen_tint_, uv, 0);
    p.flatness = eval_fraction(*flatness_, uv, 0);
    p.clearcoat = eval_fraction(*clearcoat_, uv, 0);
    const float spec_trans = eval_fraction(*spec_trans_, uv, 0);
    p.brdf = (1 - p.metallic) * (1 - spec_trans);
    p.bsdf = (1 - p.metallic) * spec_trans;
    const Vec2 alpha = principled_alphas(p.roughness, eval_fraction(*anisotropic_, uv, 0));
    p.dist = MicrofacetDistribution(MicrofacetDistribution::Type::GGX, alpha.x, alpha.y);
    const float gloss = eval_fraction(*clearcoat_gloss_, uv, 0);
    p.clearcoat_alpha = 0.1f + (0.001f - 0.1f) * gloss;
    return p;
  }

  Choice choice(const Inputs& p, bool outside) const {
    if (!outside) return {0, 0, 1};
    const float d = p.brdf * rate_diffuse_, c = 0.25f * p.clearcoat * rate_clearcoat_, s = rate_specular_;
    const float total = d + c + s;
    return {d / total, c / total, s / total};
  }

  // Within the specular lobes, the probability of reflecting off a facet
  // with dielectric Fresnel F: outside, the opaque part always reflects.
  static float reflect_probability(const Inputs& p, bool outside, float F) {
    return outside ? 1 - p.bsdf * (1 - F) : F;
  }

  Color specular_fresnel(const Inputs& p, float cos_i, float F_dielectric) const {
    Color F = Color((1 - p.metallic) * (1 - p.spec_tint) * F_dielectric);
    if (p.metallic > 0) F += p.metallic * schlick_fresnel(p.base, cos_i, eta_);
    if (p.spec_tint > 0)
      F += (1 - p.metallic) * p.spec_tint * schlick_fresnel(tint_of(p.base) * normal_reflectance(eta_), cos_i, eta_);
    return F;
  }

  Evaluation evaluate(const Inputs& p, TransportMode mode, Vec3 wo, Vec3 wi) const {
    const bool outside = wo.z > 0;
    if (!outside && !(p.bsdf > 0)) return {};
    const Choice c = choice(p, outside);
    const float cos_o = std::abs(wo.z), cos_i = std::abs(wi.z);
    Evaluation e;
    if (wo.z * wi.z > 0) {
      const Vec3 m = normalize(outside ? wo + wi : -(wo + wi));
      const float wo_m = dot(wo, m), wi_m = dot(wi, m);
      if (wo_m * wo.z <= 0 || wi_m * wi.z <= 0) return {};
      const float F_d = fresnel_dielectric(wo_m, eta_).F;
      const float specular_pdf = p.dist.pdf(outside ? wo : -wo, m) / (4 * std::abs(wo_m));
      const float D = p.dist.D(m), G = p.dist.G1(wo, m) * p.dist.G1(wi, m);
      const float shape = D * G / (4 * cos_o * cos_i);
      e.pdf = c.specular * reflect_probability(p, outside, F_d) * specular_pdf;
      if (!outside) {
        e.f = Color(p.bsdf * F_d * shape);
        return e;
      }
      e.f = specular_fresnel(p, wo_m, F_d) * shape;
      if (p.brdf > 0) {
        e.f += diffuse_with_sheen(p.base, p.brdf, cos_o, cos_i, wi_m, p.roughness, p.flatness, p.sheen, p.sheen_tint);
        e.pdf += c.diffuse * cosine_hemisphere_pdf(cos_i);
      }
      if (p.clearcoat > 0) {
        const Gtr1 coat{p.clearcoat_alpha};
        const float F_c = 0.04f + 0.96f * schlick_weight(wo_m);
        e.f += Color(0.25f * p.clearcoat * F_c * coat.D(m) * clearcoat_G(wo, wi, m) / (4 * cos_o * cos_i));
        e.pdf += c.clearcoat * coat.D(m) * m.z / (4 * wo_m);
      }
      return e;
    }
    if (!(p.bsdf > 0)) return {};
    // Refraction: eta_o wo + eta_i wi lies along the facet normal (Snell).
    const float eta = outside ? eta_ : 1 / eta_;  // the index on wi's side over wo's
    Vec3 m = wo + wi * eta;
    const float len2 = squared_length(m);
    if (!(len2 > 0)) return {};
    m = m / std::sqrt(len2);
    if (m.z < 0) m = -m;
    const float wo_m = dot(wo, m), wi_m = dot(wi, m);
    if (wo_m * wo.z <= 0 || wi_m * wi.z <= 0) return {};
    const float F_d = fresnel_dielectric(wo_m, eta_).F;
    if (F_d >= 1) return {};
    const float denom = wo_m + eta * wi_m;
    const float D = p.dist.D(m), G = p.dist.G1(wo, m) * p.dist.G1(wi, m);
    const float scale = mode == TransportMode::Radiance ? 1 : eta * eta;
    const float f = (1 - F_d) * D * G * std::abs(wo_m * wi_m) * scale / (cos_o * cos_i * denom * denom);
    const float jacobian = eta * eta * std::abs(wi_m) / (denom * denom);
    e.f = sqrt_color(p.base) * (p.bsdf * f);
    e.pdf = c.specular * (1 - reflect_probability(p, outside, F_d)) * p.dist.pdf(outside ? wo : -wo, m) * jacobian;
    return e;
  }

  std::shared_ptr<Texture> base_color_, roughness_, anisotropic_, metallic_, spec_trans_, spec_tint_, sheen_,
      sheen_tint_, flatness_, clearcoat_, clearcoat_gloss_;
  float eta_;
  float rate_diffuse_, rate_specular_, rate_clearcoat_;
  bool transmits_;
};

std::vector<ParamSpec> params() {
  return {{"base_color", ParamType::Texture, "0.5", "colour of the diffuse base, the metal and the glass"},
          {"roughness", ParamType::Texture, "0.5", "roughness of the specular lobes and the diffuse retro-reflection"},
          {"anisotropic", ParamType::Texture, "0", "stretches the specular roughness along the tangent"},
          {"metallic", ParamType::Texture, "0", "blends the dielectric material into a metal tinted by base_color"},
          {"spec_trans", ParamType::Texture, "0", "blends the opaque base into rough glass"},
          {"eta", ParamType::Float, std::nullopt, "relative index of refraction of the glass and the specular lobe"},
          {"specular", ParamType::Float, "0.5",
           "the specular lobe's reflectance at normal incidence over 0.08 "
           "(sets eta; give one or the other)"},
          {"spec_tint", ParamType::Texture, "0", "tints the dielectric reflection towards base_color"},
          {"sheen", ParamType::Texture, "0", "strength of the grazing sheen, as of cloth"},
          {"sheen_tint", ParamType::Texture, "0", "tints the sheen towards base_color"},
          {"flatness", ParamType::Texture, "0", "blends the diffuse lobe into Burley's flat, subsurface-like one"},
          {"clearcoat", ParamType::Texture, "0", "strength of the clear varnish lobe"},
          {"clearcoat_gloss", ParamType::Texture, "0", "glossiness of the varnish (0: alpha 0.1, 1: alpha 0.001)"},
          {"diffuse_reflectance_sampling_rate", ParamType::Float, "1", "relative rate of sampling the diffuse lobe"},
          {"main_specular_sampling_rate", ParamType::Float, "1", "relative rate of sampling the specular lobes"},
          {"clearcoat_sampling_rate", ParamType::Float, "1", "relative rate of sampling the clearcoat"}};
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(PrincipledBsdf, "bsdf", "principled", params(), {});

}  // namespace caustica
