// principledthin: Burley's principled material for thin sheets (2015's thin
// surface mode), as Mitsuba 3 names its parameters: leaves, paper, cloth,
// a pane of glass with no inside. Both faces are the same: with wo turned
// to the upper side (and wi with it), and the weights
// diffuse = (1 - spec_trans)(1 - diff_trans / 2), d_t = (1 - spec_trans) diff_trans / 2,
// it is the sum of
//
//   diffuse          diffuse base / pi  burley_diffuse(...)        (principled_lobes.h)
//   sheen            diffuse sheen  lerp(1, base / lum(base), sheen_tint)  (1 - cos_d)^5
//   specular         spec_trans  F D G / (4 cos_o cos_i)
//   glass            spec_trans base (1 - F_d) D' G' / (4 cos_o cos_i)
//   diffuse through  d_t base / pi
//
// Light passing through the sheet keeps its direction on average: the glass
// lobe is the reflection lobe turned through the sheet (wi mirrored to the
// upper side before its half vector is taken), with roughness scaled by
// 0.65 eta - 0.35 (Burley 2015, figure 15) in D' and G'. D and G are
// anisotropic GGX with Smith's separable masking, F blends the dielectric's
// exact Fresnel F_d (at index eta) with Schlick's tinted by spec_tint, as in
// `principled`. Nothing bends, so the sheet has one medium on both sides.
// Sampling chooses a lobe in proportion to spec_trans / 2, spec_trans / 2,
// diffuse and d_t (each times its sampling rate): GGX visible normals for
// the specular and glass lobes, cosine-weighted hemispheres for the
// diffuse ones.
//
//   <bsdf type="principledthin">
//       <rgb name="base_color" value="0.2, 0.5, 0.1"/>
//       <float name="diff_trans" value="0.6"/>
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

Vec3 mirrored(Vec3 w) { return {w.x, w.y, -w.z}; }

class PrincipledThinBsdf final : public Bsdf {
 public:
  explicit PrincipledThinBsdf(const Properties& props)
      : base_color_(read_reflectance(props, "base_color")),
        roughness_(read_fraction(props, "roughness")),
        anisotropic_(read_fraction(props, "anisotropic")),
        spec_trans_(read_fraction(props, "spec_trans")),
        spec_tint_(read_fraction(props, "spec_tint")),
        sheen_(read_fraction(props, "sheen")),
        sheen_tint_(read_fraction(props, "sheen_tint")),
        flatness_(read_fraction(props, "flatness")),
        diff_trans_(read_texture(props, "diff_trans")),
        eta_(read_texture(props, "eta")),
        rate_specular_(read_sampling_rate(props, "specular_reflectance_sampling_rate")),
        rate_glass_(read_sampling_rate(props, "specular_transmittance_sampling_rate")),
        rate_diffuse_(read_sampling_rate(props, "diffuse_reflectance_sampling_rate")),
        rate_through_(read_sampling_rate(props, "diffuse_transmittance_sampling_rate")) {
    const ValueRange d = diff_trans_->range(), e = eta_->range();
    if (!(d.lowest >= 0 && d.highest <= 2)) throw props.error("diff_trans", "must lie in [0, 2]");
    if (!(e.lowest > 0 && std::isfinite(e.highest))) throw props.error("eta", "must be positive");
  }

  uint32_t lobes() const override {
    uint32_t out = kDiffuseReflection;
    if (spec_trans_->range().highest > 0) out |= kGlossyReflection | kGlossyTransmission;
    if (diff_trans_->range().highest > 0) out |= kDiffuseTransmission;
    return out;
  }

  Color eval(const BsdfContext& ctx, Vec3 wo, Vec3 wi) const override {
    if (wo.z == 0 || wi.z == 0) return {};
    return evaluate(at(ctx), up(wo, wo), up(wo, wi)).f;
  }

  float pdf(const BsdfContext& ctx, Vec3 wo, Vec3 wi) const override {
    if (wo.z == 0 || wi.z == 0) return 0;
    return evaluate(at(ctx), up(wo, wo), up(wo, wi)).pdf;
  }

  std::optional<BsdfSample> sample(const BsdfContext& ctx, Vec3 wo, float u_lobe, Vec2 u) const override {
    if (wo.z == 0) return std::nullopt;
    const Inputs p = at(ctx);
    const Vec3 o = up(wo, wo);
    Vec3 i;
    uint32_t lobe;
    if (u_lobe < p.specular) {
      i = reflect(o, p.dist.sample(o, u));
      lobe = kGlossyReflection;
    } else if (u_lobe < p.specular + p.glass) {
      i = mirrored(reflect(o, p.glass_dist.sample(o, u)));
      lobe = kGlossyTransmission;
    } else if (u_lobe < p.specular + p.glass + p.diffuse) {
      i = square_to_cosine_hemisphere(u);
      lobe = kDiffuseReflection;
    } else {
      i = mirrored(square_to_cosine_hemisphere(u));
      lobe = kDiffuseTransmission;
    }
    if (i.z == 0 || ((lobe & kTransmission) != 0) != (i.z < 0)) return std::nullopt;
    const Evaluation e = evaluate(p, o, i);
    if (!(e.pdf > 0) || !std::isfinite(e.pdf) || !e.f.is_finite()) return std::nullopt;
    return BsdfSample{up(wo, i), e.f, e.pdf, lobe, 1};
  }

  // An estimate for the albedo AOV: the diffuse lobes' weights and the
  // specular ones' at the dielectric's Fresnel for wo.
  Color albedo(const BsdfContext& ctx, Vec3 wo) const override {
    if (wo.z == 0) return {};
    const Inputs p = at(ctx);
    const float F = fresnel_dielectric(std::abs(wo.z), p.eta).F, spec = 1 - p.w_diffuse - p.w_through;
    return p.base * (p.w_diffuse + p.w_through + spec * (1 - F)) + Color(spec * F);
  }

 private:
  // The textures' values at a shading point and the lobes' probabilities.
  struct Inputs {
    Color base;
    float roughness, spec_tint, sheen, sheen_tint, flatness, eta;
    float w_diffuse, w_through;  // the diffuse lobes' weights
    MicrofacetDistribution dist{MicrofacetDistribution::Type::GGX, 1, 1},
        glass_dist{MicrofacetDistribution::Type::GGX, 1, 1};
    float specular, glass, diffuse, through;  // the probabilities of choosing each lobe
  };

  struct Evaluation {
    Color f;
    float pdf = 0;
  };

  // w as seen with `reference` turned to the upper side: both faces are alike.
  static Vec3 up(Vec3 reference, Vec3 w) { return reference.z > 0 ? w : -w; }

  Inputs at(const BsdfContext& ctx) const {
    const Vec2 uv = ctx.uv;
    Inputs p;
    p.base = base_color_->eval(uv);
    p.roughness = eval_fraction(*roughness_, uv, 0.5f);
    p.spec_tint = eval_fraction(*spec_tint_, uv, 0);
    p.sheen = eval_fraction(*sheen_, uv, 0);
    p.sheen_tint = eval_fraction(*sheen_tint_, uv, 0);
    p.flatness = eval_fraction(*flatness_, uv, 0);
    p.eta = std::max(eta_->eval(uv).luminance(), 1e-3f);
    const float spec_trans = eval_fraction(*spec_trans_, uv, 0);
    const float diff_trans = std::clamp(diff_trans_->eval(uv).luminance() / 2, 0.0f, 1.0f);
    p.w_diffuse = (1 - spec_trans) * (1 - diff_trans);
    p.w_through = (1 - spec_trans) * diff_trans;
    const float anisotropic = eval_fraction(*anisotropic_, uv, 0);
    const Vec2 alpha = principled_alphas(p.roughness, anisotropic);
    p.dist = MicrofacetDistribution(MicrofacetDistribution::Type::GGX, alpha.x, alpha.y);
    const Vec2 glass_alpha = principled_alphas(std::max(0.0f, 0.65f * p.eta - 0.35f) * p.roughness, anisotropic);
    p.glass_dist = MicrofacetDistribution(MicrofacetDistribution::Type::GGX, glass_alpha.x, glass_alpha.y);
    const float s = 0.5f * spec_trans * rate_specular_, g = 0.5f * spec_trans * rate_glass_;
    const float d = p.w_diffuse * rate_diffuse_, t = p.w_through * rate_through_;
    const float total = s + g + d + t;
    p.specular = s / total, p.glass = g / total, p.diffuse = d / total, p.through = t / total;
    return p;
  }

  // f and pdf with wo on the upper side (o.z > 0).
  Evaluation evaluate(const Inputs& p, Vec3 o, Vec3 i) const {
    const float cos_o = o.z, cos_i = std::abs(i.z);
    const float spec_trans = 1 - p.w_diffuse - p.w_through;
    // Through the sheet the lobe is the reflection's, of i mirrored back.
    const Vec3 r = i.z > 0 ? i : mirrored(i);
    const Vec3 m = normalize(o + r);
    const float o_m = dot(o, m), r_m = dot(r, m);
    Evaluation e;
    if (o_m > 0 && r_m > 0 && spec_trans > 0) {
      const float F_d = fresnel_dielectric(o_m, p.eta).F;
      const MicrofacetDistribution& dist = i.z > 0 ? p.dist : p.glass_dist;
      const float shape = dist.D(m) * dist.G1(o, m) * dist.G1(r, m) / (4 * cos_o * cos_i);
      const float density = dist.pdf(o, m) / (4 * o_m);
      if (i.z > 0) {
        Color F = Color(F_d);
        if (p.spec_tint > 0)
          F = F * (1 - p.spec_tint) +
              schlick_fresnel(tint_of(p.base) * normal_reflectance(p.eta), o_m, p.eta) * p.spec_tint;
        e.f += F * (spec_trans * shape);
        e.pdf += p.specular * density;
      } else {
        e.f += p.base * (spec_trans * (1 - F_d) * shape);
        e.pdf += p.glass * density;
      }
    }
    if (i.z > 0) {
      if (p.w_diffuse > 0)
        e.f +=
            diffuse_with_sheen(p.base, p.w_diffuse, cos_o, cos_i, r_m, p.roughness, p.flatness, p.sheen, p.sheen_tint);
      e.pdf += p.diffuse * cosine_hemisphere_pdf(cos_i);
    } else {
      e.f += p.base * (p.w_through * kInvPi);
      e.pdf += p.through * cosine_hemisphere_pdf(cos_i);
    }
    return e;
  }

  std::shared_ptr<Texture> base_color_, roughness_, anisotropic_, spec_trans_, spec_tint_, sheen_, sheen_tint_,
      flatness_, diff_trans_, eta_;
  float rate_specular_, rate_glass_, rate_diffuse_, rate_through_;
};

std::vector<ParamSpec> params() {
  return {{"base_color", ParamType::Texture, "0.5", "colour of the diffuse lobes and of light passing through"},
          {"roughness", ParamType::Texture, "0.5", "roughness of the specular lobes and the diffuse retro-reflection"},
          {"anisotropic", ParamType::Texture, "0", "stretches the specular roughness along the tangent"},
          {"spec_trans", ParamType::Texture, "0",
           "blends the diffuse sheet into a specular one (reflecting and "
           "letting light through)"},
          {"eta", ParamType::Texture, "1.5", "index of refraction of the sheet's faces (their Fresnel)"},
          {"spec_tint", ParamType::Texture, "0", "tints the specular reflection towards base_color"},
          {"sheen", ParamType::Texture, "0", "strength of the grazing sheen, as of cloth"},
          {"sheen_tint", ParamType::Texture, "0", "tints the sheen towards base_color"},
          {"flatness", ParamType::Texture, "0", "blends the diffuse lobe into Burley's flat, subsurface-like one"},
          {"diff_trans", ParamType::Texture, "0", "share of the diffuse light sent through the sheet, 0 to 2 (2: all)"},
          {"specular_reflectance_sampling_rate", ParamType::Float, "1", "relative rate of sampling the specular lobe"},
          {"specular_transmittance_sampling_rate", ParamType::Float, "1", "relative rate of sampling the glass lobe"},
          {"diffuse_reflectance_sampling_rate", ParamType::Float, "1", "relative rate of sampling the diffuse lobe"},
          {"diffuse_transmittance_sampling_rate", ParamType::Float, "1",
           "relative rate of sampling the diffuse light through"}};
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(PrincipledThinBsdf, "bsdf", "principledthin", params(), {});

}  // namespace caustica
