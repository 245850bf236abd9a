// diffuse: the ideal Lambertian reflector, f = reflectance / pi.
//
// One-sided: light arriving from below the shading normal is not reflected
// (wrap it in `twosided` for sheets seen from both sides).
//
//   <bsdf type="diffuse">
//       <rgb name="reflectance" value="0.2, 0.25, 0.7"/>
//   </bsdf>

#include "core/bsdf/bsdf.h"
#include "core/bsdf/reflectance_at.h"
#include "core/math/constants.h"
#include "core/registry/properties.h"
#include "core/sampling/warp.h"
#include "core/texture/texture_parameter.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class DiffuseBsdf final : public Bsdf {
 public:
  explicit DiffuseBsdf(const Properties& props) : reflectance_(read_reflectance(props, "reflectance")) {}

  uint32_t lobes() const override { return kDiffuseReflection; }
  bool reads_tangents() const override { return false; }
  bool renders_spectral() const override { return true; }

  Color eval(const BsdfContext& ctx, Vec3 wo, Vec3 wi) const override {
    if (cos_theta(wo) <= 0 || cos_theta(wi) <= 0) return {};
    return reflectance_at(*reflectance_, ctx) * kInvPi;
  }

  float pdf(const BsdfContext&, Vec3 wo, Vec3 wi) const override {
    if (cos_theta(wo) <= 0) return 0;
    return cosine_hemisphere_pdf(cos_theta(wi));
  }

  std::optional<BsdfSample> sample(const BsdfContext& ctx, Vec3 wo, float, Vec2 u) const override {
    if (cos_theta(wo) <= 0) return std::nullopt;
    const Vec3 wi = square_to_cosine_hemisphere(u);
    const float pdf = cosine_hemisphere_pdf(cos_theta(wi));
    if (pdf <= 0) return std::nullopt;
    return BsdfSample{wi, reflectance_at(*reflectance_, ctx) * kInvPi, pdf, kDiffuseReflection, 1};
  }

  Color albedo(const BsdfContext& ctx, Vec3 wo) const override {
    return cos_theta(wo) > 0 ? reflectance_at(*reflectance_, ctx) : Color();
  }

 private:
  std::shared_ptr<Texture> reflectance_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(DiffuseBsdf, "bsdf", "diffuse",
                         {{"reflectance", ParamType::Texture, "0.5",
                           "diffuse reflectance: the fraction of light scattered, per channel"}},
                         {});

}  // namespace caustica
