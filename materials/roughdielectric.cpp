// roughdielectric: a rough interface between two dielectrics (frosted glass,
// etched glass, rough water), after Walter et al., "Microfacet Models for
// Refraction through Rough Surfaces", EGSR 2007.
//
// The surface is a field of smooth dielectric facets whose normals m follow
// a Beckmann or GGX distribution D with Smith masking-shadowing G. A facet
// reflects with the Fresnel reflectance F(wo.m) and refracts the rest. With
// eta_o, eta_i the indices on the sides of wo and wi and eta = eta_i / eta_o:
//
//   reflection    f = F D G / (4 |wo.z| |wi.z|),             m = normalize(wo + wi)
//   transmission  f = (1 - F) D G |wo.m| |wi.m| eta^2 s
//                     / (|wo.z| |wi.z| (wo.m + eta wi.m)^2),  m = normalize(wo + eta wi)
//
// with m turned to the outside (+z), and s = 1 in importance transport and
// s = 1 / eta^2 in radiance transport (radiance is compressed by eta^2 on
// entering a denser medium; see `dielectric`). sample() draws a facet
// normal seen from wo (GGX: visible normals; Beckmann: D(m) cos(theta_m)),
// from the mirrored direction when wo is inside, then reflects with
// probability F and refracts otherwise. Samples that would leave on the
// wrong side, or meet a facet from behind, are rejected, so the sampling
// density integrates to less than 1 (most for rough surfaces at grazing
// angles). albedo() reports the smooth interface's
// specular_reflectance F + specular_transmittance (1 - F) at wo.
//
// Equal indices make the facets invisible: light passes straight through as
// a delta transmission lobe, as for `dielectric`. `dispersion` is read as
// `dielectric` reads it: every value at the path's hero wavelength.
//
// `distribution` is beckmann or ggx; alpha is the roughness (the root mean
// square slope of the facets for beckmann). alpha_u and alpha_v make it
// anisotropic, along the tangent and the bitangent: give both or neither,
// and not together with alpha; without them both are alpha.
//
//   <bsdf type="roughdielectric">
//       <string name="distribution" value="ggx"/>
//       <float name="alpha" value="0.3"/>
//       <string name="int_ior" value="bk7"/>
//   </bsdf>

#include <cmath>
#include <stdexcept>

#include "core/bsdf/bsdf.h"
#include "core/bsdf/dielectric_interface.h"
#include "core/bsdf/fresnel.h"
#include "core/bsdf/microfacet_params.h"
#include "core/bsdf/reflectance_at.h"
#include "core/registry/properties.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class RoughDielectricBsdf final : public Bsdf {
 public:
  explicit RoughDielectricBsdf(const Properties& props)
      : interface_(props), roughness_(props), sample_visible_(props.get_bool("sample_visible")) {}

  bool reads_tangents() const override { return false; }
  bool renders_spectral() const override { return true; }
  bool disperses() const override { return interface_.disperses(); }
  uint32_t lobes() const override {
    return index_matched() ? kDeltaTransmission : kGlossyReflection | kGlossyTransmission;
  }

  Color eval(const BsdfContext& ctx, Vec3 wo, Vec3 wi) const override {
    const float eta = interface_.eta_at(ctx);
    const auto m = half_vector(wo, wi, eta);
    return m ? evaluate(roughness_.at(ctx.uv), ctx, eta, wo, wi, *m).f : Color();
  }

  float pdf(const BsdfContext& ctx, Vec3 wo, Vec3 wi) const override {
    const float eta = interface_.eta_at(ctx);
    const auto m = half_vector(wo, wi, eta);
    return m ? evaluate(roughness_.at(ctx.uv), ctx, eta, wo, wi, *m).pdf : 0;
  }

  std::optional<BsdfSample> sample(const BsdfContext& ctx, Vec3 wo, float u_lobe, Vec2 u) const override {
    if (wo.z == 0) return std::nullopt;
    if (index_matched())
      return BsdfSample{-wo, reflectance_at(*interface_.transmittance, ctx) / std::abs(wo.z), 1, kDeltaTransmission, 1};
    // Facets are seen from wo's side; the distribution is symmetric under
    // m -> (-m.x, -m.y, m.z), so wo inside samples as -wo outside.
    const MicrofacetDistribution distribution = roughness_.at(ctx.uv);
    const Vec3 m = sample_visible_ ? distribution.sample(wo.z > 0 ? wo : -wo, u) : distribution.sample_D(u);
    const float wo_m = dot(wo, m);
    if (wo_m * wo.z <= 0) return std::nullopt;  // a back-facing facet (Beckmann samples those)
    const float eta = interface_.eta_at(ctx);
    const DielectricFresnel fr = fresnel_dielectric(wo_m, eta);
    Vec3 wi;
    uint32_t lobe;
    if (u_lobe < fr.F) {
      wi = reflect(wo, m);
      lobe = kGlossyReflection;
      if (wi.z * wo.z <= 0) return std::nullopt;
    } else {
      wi = refract(wo, m, fr.cos_t, fr.eta_ti);
      lobe = kGlossyTransmission;
      if (wi.z * wo.z >= 0) return std::nullopt;
    }
    const Evaluation e = evaluate(distribution, ctx, eta, wo, wi, m);
    if (!(e.pdf > 0)) return std::nullopt;
    return BsdfSample{wi, e.f, e.pdf, lobe, lobe == kGlossyTransmission ? fr.eta_it : 1.0f};
  }

  Color albedo(const BsdfContext& ctx, Vec3 wo) const override {
    const float F = index_matched() ? 0 : fresnel_dielectric(wo.z, interface_.eta_at(ctx)).F;
    return reflectance_at(*interface_.reflectance, ctx) * F + reflectance_at(*interface_.transmittance, ctx) * (1 - F);
  }

 private:
  struct Evaluation {
    Color f;
    float pdf = 0;
  };

  bool index_matched() const { return !interface_.disperses() && interface_.eta == 1; }

  // The facet normal that turns wo into wi, by reflection or refraction,
  // oriented to the outside; none where no facet seen from both directions
  // does. eta is the relative index (inside over outside).
  std::optional<Vec3> half_vector(Vec3 wo, Vec3 wi, float eta) const {
    if (wo.z == 0 || wi.z == 0 || index_matched()) return std::nullopt;
    const bool reflection = wo.z * wi.z > 0;
    // For refraction eta_o wo + eta_i wi is along the facet normal (Snell).
    Vec3 m = reflection ? wo + wi : wo + wi * (wo.z > 0 ? eta : 1 / eta);
    const float len2 = squared_length(m);
    if (!(len2 > 0)) return std::nullopt;
    m = m / std::sqrt(len2);
    if (m.z < 0) m = -m;
    if (dot(wo, m) * wo.z <= 0 || dot(wi, m) * wi.z <= 0) return std::nullopt;
    return m;
  }

  // f and pdf of the pair (wo, wi) through facet normal m (m.z > 0), with
  // the distribution at the point and the relative index eta_inside.
  Evaluation evaluate(const MicrofacetDistribution& distribution, const BsdfContext& ctx, float eta_inside, Vec3 wo,
                      Vec3 wi, Vec3 m) const {
    const float D = distribution.D(m), G = distribution.G(wo, wi, m);
    const float wo_m = dot(wo, m), wi_m = dot(wi, m);
    // Density of the facet normal as sampled from wo's side.
    const float pdf_m = sample_visible_ ? distribution.pdf(wo.z > 0 ? wo : -wo, m) : distribution.pdf_D(m);
    if (!(D > 0) || !(pdf_m > 0)) return {};
    const float F = fresnel_dielectric(wo_m, eta_inside).F;
    const float cos_o = std::abs(wo.z), cos_i = std::abs(wi.z);
    if (wo.z * wi.z > 0) {
      // Jacobian of the reflected direction: d(omega_m) / d(omega_i) = 1 / (4 |wi.m|).
      const float f = F * D * G / (4 * cos_o * cos_i);
      return {reflectance_at(*interface_.reflectance, ctx) * f, F * pdf_m / (4 * std::abs(wo_m))};
    }
    if (F >= 1) return {};
    const float eta = wo.z > 0 ? eta_inside : 1 / eta_inside;  // index on wi's side over wo's
    const float denom = wo_m + eta * wi_m;
    // Jacobian of the refracted direction: eta^2 |wi.m| / (wo.m + eta wi.m)^2.
    const float jacobian = eta * eta * std::abs(wi_m) / (denom * denom);
    const float scale = ctx.mode == TransportMode::Radiance ? 1 : eta * eta;
    const float f = (1 - F) * D * G * std::abs(wo_m * wi_m) * scale / (cos_o * cos_i * denom * denom);
    const Evaluation e{reflectance_at(*interface_.transmittance, ctx) * f, (1 - F) * pdf_m * jacobian};
    if (!e.f.is_finite() || !std::isfinite(e.pdf)) return {};
    return e;
  }

  DielectricInterface interface_;
  MicrofacetRoughness roughness_;
  bool sample_visible_;
};

std::vector<ParamSpec> params() {
  auto p = microfacet_params(true, true);
  p.insert(p.end(),
           {{"int_ior", ParamType::Ior, "bk7",
             "index of refraction inside (below the normal); a number or a name such as water"},
            {"ext_ior", ParamType::Ior, "air", "index of refraction outside"},
            dispersion_param(),
            {"specular_reflectance", ParamType::Texture, "1", "scales the reflected light (1 is physical)"},
            {"specular_transmittance", ParamType::Texture, "1", "scales the transmitted light (1 is physical)"},
            {"sample_visible", ParamType::Boolean, "true", "sample only the facet normals visible from wo"}});
  return p;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(RoughDielectricBsdf, "bsdf", "roughdielectric", CAUSTICA_UNITY_ID::params(), {});

}  // namespace caustica
