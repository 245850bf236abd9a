// twosided: makes a one-sided BSDF scatter on both faces of a surface.
//
// Takes one nested BSDF, used on both sides, or two: the first for the front
// (the side the normal points to) and the second for the back. Seen from the
// back, directions are mirrored through the surface before the nested BSDF
// is asked. Transmission lobes cannot be wrapped.
//
//   <bsdf type="twosided">
//       <bsdf type="diffuse"/>
//   </bsdf>

#include <optional>

#include "core/bsdf/bsdf.h"
#include "core/bsdf/combined_traits.h"
#include "core/registry/properties.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

Vec3 flip(Vec3 w) { return {w.x, w.y, -w.z}; }

class TwoSidedBsdf final : public Bsdf {
 public:
  explicit TwoSidedBsdf(const Properties& props) {
    auto nested = props.children<Bsdf>("bsdf");
    if (nested.empty() || nested.size() > 2)
      throw SceneError(props.where(),
                       "bsdf 'twosided' takes one or two nested bsdfs, found " + std::to_string(nested.size()));
    front_ = nested.front();
    back_ = nested.back();
    traits_.emplace(*front_, *back_);
    if (traits_->lobes & kTransmission)
      throw SceneError(props.where(), "bsdf 'twosided' cannot wrap a bsdf that transmits light");
  }

  uint32_t lobes() const override { return traits_->lobes; }
  bool reads_tangents() const override { return traits_->reads_tangents; }
  bool renders_spectral() const override { return traits_->renders_spectral; }
  bool disperses() const override { return traits_->disperses; }

  Color eval(const BsdfContext& ctx, Vec3 wo, Vec3 wi) const override {
    return wo.z > 0 ? front_->eval(ctx, wo, wi) : back_->eval(ctx, flip(wo), flip(wi));
  }

  float pdf(const BsdfContext& ctx, Vec3 wo, Vec3 wi) const override {
    return wo.z > 0 ? front_->pdf(ctx, wo, wi) : back_->pdf(ctx, flip(wo), flip(wi));
  }

  std::optional<BsdfSample> sample(const BsdfContext& ctx, Vec3 wo, float u_lobe, Vec2 u) const override {
    if (wo.z > 0) return front_->sample(ctx, wo, u_lobe, u);
    auto s = back_->sample(ctx, flip(wo), u_lobe, u);
    if (s) s->wi = flip(s->wi);
    return s;
  }

  Color albedo(const BsdfContext& ctx, Vec3 wo) const override {
    return wo.z > 0 ? front_->albedo(ctx, wo) : back_->albedo(ctx, flip(wo));
  }

 private:
  std::shared_ptr<Bsdf> front_, back_;
  std::optional<CombinedTraits> traits_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(TwoSidedBsdf, "bsdf", "twosided", {}, {"bsdf"});

}  // namespace caustica
