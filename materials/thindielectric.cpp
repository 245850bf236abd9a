// thindielectric: a thin dielectric sheet, such as a window pane.
//
// Light entering the sheet bounces between its two parallel faces; summing
// the reflected and transmitted parts of all bounces gives
//   R' = R + T^2 R / (1 - R^2) = 2 R / (1 + R),   T' = 1 - R',
// with R the Fresnel reflectance of one face at the incident angle and
// T = 1 - R (both faces see the same angle, from either side). The
// transmitted light leaves parallel to where it came in, so transmission
// is modelled as passing straight through (wi = -wo, eta 1) and no
// radiance scaling applies. Both lobes are delta lobes, sampled with
// probabilities R' and T', so each sample's weight f |cos| / pdf is
// specular_reflectance or specular_transmittance. The sheet looks the same
// from both sides.
//
//   <bsdf type="thindielectric">
//       <string name="int_ior" value="bk7"/>
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

class ThinDielectricBsdf final : public DeltaBsdf {
 public:
  explicit ThinDielectricBsdf(const Properties& props) : interface_(props, false) {}

  uint32_t lobes() const override { return kDeltaReflection | kDeltaTransmission; }
  bool renders_spectral() const override { return true; }

  std::optional<BsdfSample> sample(const BsdfContext& ctx, Vec3 wo, float u_lobe, Vec2) const override {
    if (wo.z == 0) return std::nullopt;
    const float R = reflectance(std::abs(wo.z)), T = 1 - R;
    const float inv_cos = 1 / std::abs(wo.z);  // |wi.z| = |wo.z| for both lobes
    if (u_lobe < R)
      return BsdfSample{Vec3(-wo.x, -wo.y, wo.z), reflectance_at(*interface_.reflectance, ctx) * (R * inv_cos), R,
                        kDeltaReflection, 1};
    return BsdfSample{-wo, reflectance_at(*interface_.transmittance, ctx) * (T * inv_cos), T, kDeltaTransmission, 1};
  }

  Color albedo(const BsdfContext& ctx, Vec3 wo) const override {
    const float R = reflectance(std::abs(wo.z));
    return reflectance_at(*interface_.reflectance, ctx) * R + reflectance_at(*interface_.transmittance, ctx) * (1 - R);
  }

 private:
  // R' of the sheet for light arriving at cos_o > 0 from outside.
  float reflectance(float cos_o) const {
    if (interface_.eta == 1) return 0;  // index-matched: exactly transparent
    const float R = fresnel_dielectric(cos_o, interface_.eta).F;
    // R + T^2 R / (1 - R^2) with T = 1 - R, written so that R = 1 (total
    // internal reflection at the first face, for eta < 1) stays finite.
    return 2 * R / (1 + R);
  }

  DielectricInterface interface_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(
    ThinDielectricBsdf, "bsdf", "thindielectric",
    {{"int_ior", ParamType::Ior, "bk7", "index of refraction of the sheet; a number or a name such as water"},
     {"ext_ior", ParamType::Ior, "air", "index of refraction around it"},
     {"specular_reflectance", ParamType::Texture, "1", "scales the reflected light (1 is physical)"},
     {"specular_transmittance", ParamType::Texture, "1", "scales the transmitted light (1 is physical)"}},
    {});

}  // namespace caustica
