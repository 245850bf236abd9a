// dielectric: a smooth interface between two dielectrics (glass, water).
//
// Light is reflected with the unpolarised Fresnel reflectance F and
// refracted by Snell's law with 1 - F; beyond the critical angle (seen from
// the denser side) all of it is reflected. Both lobes are delta lobes, and
// sample() picks one with its Fresnel probability, so the weight
// f |cos| / pdf of a sample is specular_reflectance for reflection and
// specular_transmittance for refraction, times the radiance factor below.
//
// Radiance is not conserved across a refraction: it is compressed into the
// denser medium's narrower cone. In radiance transport the transmitted
// weight is therefore divided by eta^2, where eta (BsdfSample::eta) is the
// index on the side of wi over the index on the side of wo; importance
// transport carries no such factor. So a white dielectric's albedo
// estimate is 1 in importance mode and F + (1 - F) / eta^2 in radiance mode.
// albedo() reports specular_reflectance F + specular_transmittance (1 - F).
//
// Indices equal (int_ior = ext_ior) make an index-matched, invisible
// interface: nothing is reflected and light passes straight through.
//
// `dispersion` in place of int_ior makes the inside's index vary with
// wavelength (a prism's spectrum, a diamond's fire): the scene is then
// rendered spectrally, each bounce refracting by the index at the path's
// hero wavelength, the path going on at that wavelength alone.
//
//   <bsdf type="dielectric">
//       <string name="dispersion" value="sellmeier: 1.0396, 0.0060, 0.2318, 0.0200, 1.0105, 103.56"/>
//   </bsdf>
//
//   <bsdf type="dielectric">
//       <string name="int_ior" value="water"/>
//       <float name="ext_ior" value="1.0"/>
//   </bsdf>

#include <cmath>

#include "core/bsdf/delta_bsdf.h"
#include "core/bsdf/dielectric_interface.h"
#include "core/bsdf/fresnel.h"
#include "core/bsdf/reflectance_at.h"
#include "core/registry/properties.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class DielectricBsdf final : public DeltaBsdf {
 public:
  explicit DielectricBsdf(const Properties& props) : interface_(props) {}

  uint32_t lobes() const override { return kDeltaReflection | kDeltaTransmission; }
  bool renders_spectral() const override { return true; }
  bool disperses() const override { return interface_.disperses(); }

  std::optional<BsdfSample> sample(const BsdfContext& ctx, Vec3 wo, float u_lobe, Vec2) const override {
    if (wo.z == 0) return std::nullopt;
    const DielectricFresnel fr = fresnel(wo.z, interface_.eta_at(ctx));
    if (u_lobe < fr.F) {
      const Vec3 wi(-wo.x, -wo.y, wo.z);
      return BsdfSample{wi, reflectance_at(*interface_.reflectance, ctx) * (fr.F / std::abs(wi.z)), fr.F,
                        kDeltaReflection, 1};
    }
    const Vec3 wi = refract(wo, Vec3(0, 0, 1), fr.cos_t, fr.eta_ti);
    if (wi.z * wo.z >= 0) return std::nullopt;
    // eta_ti^2 = (index on wo's side / index on wi's side)^2.
    const float scale = ctx.mode == TransportMode::Radiance ? fr.eta_ti * fr.eta_ti : 1.0f;
    const float T = 1 - fr.F;
    return BsdfSample{wi, reflectance_at(*interface_.transmittance, ctx) * (T * scale / std::abs(wi.z)), T,
                      kDeltaTransmission, fr.eta_it};
  }

  Color albedo(const BsdfContext& ctx, Vec3 wo) const override {
    const float F = fresnel(wo.z, interface_.eta_at(ctx)).F;
    return reflectance_at(*interface_.reflectance, ctx) * F + reflectance_at(*interface_.transmittance, ctx) * (1 - F);
  }

 private:
  // Fresnel at the macro surface; an index-matched interface is exactly
  // transparent (the general formula leaves rounding residue there).
  static DielectricFresnel fresnel(float cos_o, float eta) {
    if (eta == 1) return {0, -cos_o, 1, 1};
    return fresnel_dielectric(cos_o, eta);
  }

  DielectricInterface interface_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(
    DielectricBsdf, "bsdf", "dielectric",
    {{"int_ior", ParamType::Ior, "bk7",
      "index of refraction inside (below the normal); a number or a name such as water"},
     {"ext_ior", ParamType::Ior, "air", "index of refraction outside"},
     dispersion_param(),
     {"specular_reflectance", ParamType::Texture, "1", "scales the reflected light (1 is physical)"},
     {"specular_transmittance", ParamType::Texture, "1", "scales the transmitted light (1 is physical)"}},
    {});

}  // namespace caustica
