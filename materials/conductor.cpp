// conductor: a smooth metal, a perfect mirror weighted by the Fresnel
// reflectance of a conductor with complex index of refraction eta + i k.
//
// Give either `material` or `eta` and `k`. With the defaults (eta 0, k 1)
// the Fresnel reflectance is 1 at every angle. One-sided: light arriving
// from below the shading normal is not reflected.
//
//   <bsdf type="conductor">
//       <string name="material" value="Au"/>
//   </bsdf>
//
//   <bsdf type="conductor">
//       <rgb name="eta" value="0.2, 0.92, 1.1"/>
//       <rgb name="k" value="3.9, 2.45, 2.14"/>
//   </bsdf>

#include "core/bsdf/conductor_data.h"
#include "core/bsdf/delta_bsdf.h"
#include "core/bsdf/fresnel.h"
#include "core/bsdf/reflectance_at.h"
#include "core/registry/properties.h"
#include "core/texture/texture_parameter.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class ConductorBsdf final : public DeltaBsdf {
 public:
  explicit ConductorBsdf(const Properties& props)
      : ior_(conductor_ior(props)), specular_reflectance_(read_reflectance(props, "specular_reflectance")) {}

  uint32_t lobes() const override { return kDeltaReflection; }
  bool renders_spectral() const override { return true; }

  std::optional<BsdfSample> sample(const BsdfContext& ctx, Vec3 wo, float, Vec2) const override {
    if (!(cos_theta(wo) > 0)) return std::nullopt;
    const Vec3 wi(-wo.x, -wo.y, wo.z);
    return BsdfSample{wi, reflectance(ctx, wo) / cos_theta(wo), 1, kDeltaReflection, 1};
  }

  Color albedo(const BsdfContext& ctx, Vec3 wo) const override {
    return cos_theta(wo) > 0 ? reflectance(ctx, wo) : Color();
  }

 private:
  Color reflectance(const BsdfContext& ctx, Vec3 wo) const {
    return fresnel_conductor_at(ctx, cos_theta(wo), ior_) * reflectance_at(*specular_reflectance_, ctx);
  }

  ConductorIor ior_;
  std::shared_ptr<Texture> specular_reflectance_;
};

std::vector<ParamSpec> params() {
  auto p = conductor_ior_params();
  p.push_back({"specular_reflectance", ParamType::Texture, "1", "factor on the reflectance (not physical)"});
  return p;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(ConductorBsdf, "bsdf", "conductor", params(), {});

}  // namespace caustica
