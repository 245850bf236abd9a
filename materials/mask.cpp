// mask: makes a surface partly transparent (leaves, fences, cut-outs).
//
// With probability `opacity` (the texture's luminance, as Mitsuba, clamped
// to [0, 1]) light meets the nested BSDF, otherwise it continues unchanged
// in its direction: an index-matched pass-through, a delta transmission lobe
// with wi = -wo, eta = 1 and weight f |cos| / pdf = 1. eval and pdf are the
// nested BSDF's scaled by the opacity; the pass-through lobe, being a delta,
// is reached by sampling only.
//
//   <bsdf type="mask">
//       <texture type="bitmap" name="opacity">
//           <string name="filename" value="leaf_alpha.png"/>
//           <boolean name="raw" value="true"/>
//       </texture>
//       <bsdf type="diffuse"/>
//   </bsdf>

#include <algorithm>
#include <cmath>

#include "core/bsdf/bsdf.h"
#include "core/math/constants.h"
#include "core/registry/properties.h"
#include "core/texture/texture_parameter.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class MaskBsdf final : public Bsdf {
 public:
  explicit MaskBsdf(const Properties& props)
      : opacity_(read_fraction(props, "opacity")), nested_(props.child<Bsdf>("bsdf")) {
    if (!nested_) throw SceneError(props.where(), "bsdf 'mask' takes one nested bsdf");
  }

  uint32_t lobes() const override { return nested_->lobes() | kDeltaTransmission; }
  bool reads_tangents() const override { return nested_->reads_tangents(); }
  bool renders_spectral() const override { return nested_->renders_spectral(); }
  bool disperses() const override { return nested_->disperses(); }

  Color eval(const BsdfContext& ctx, Vec3 wo, Vec3 wi) const override {
    const float a = opacity(ctx);
    return a > 0 ? nested_->eval(ctx, wo, wi) * a : Color();
  }

  float pdf(const BsdfContext& ctx, Vec3 wo, Vec3 wi) const override {
    const float a = opacity(ctx);
    return a > 0 ? nested_->pdf(ctx, wo, wi) * a : 0;
  }

  std::optional<BsdfSample> sample(const BsdfContext& ctx, Vec3 wo, float u_lobe, Vec2 u) const override {
    const float a = opacity(ctx);
    if (u_lobe < a) {
      auto s = nested_->sample(ctx, wo, std::min(u_lobe / a, kOneMinusEpsilon), u);
      if (s) {
        s->f *= a;
        s->pdf *= a;
      }
      return s;
    }
    if (wo.z == 0) return std::nullopt;
    const float pass = 1 - a;
    return BsdfSample{-wo, Color(pass / std::abs(wo.z)), pass, kDeltaTransmission, 1};
  }

  Color albedo(const BsdfContext& ctx, Vec3 wo) const override {
    const float a = opacity(ctx);
    return nested_->albedo(ctx, wo) * a + Color(1 - a);
  }

 private:
  float opacity(const BsdfContext& ctx) const { return eval_fraction(*opacity_, ctx.uv, 1.0f); }

  std::shared_ptr<Texture> opacity_;
  std::shared_ptr<Bsdf> nested_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(MaskBsdf, "bsdf", "mask",
                         {{"opacity", ParamType::Texture, "0.5",
                           "fraction of light the nested bsdf scatters; the rest passes straight through"}},
                         {"bsdf"});

}  // namespace caustica
