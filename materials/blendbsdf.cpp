// blendbsdf: a mixture of two BSDFs, (1 - weight) of the first and weight
// of the second (weight 0 is the first alone, 1 the second alone, as
// Mitsuba's blendbsdf). Sampling picks one of them with those
// probabilities; a non-delta sample is then weighed with the whole mixture's
// eval and pdf, so it is the mixture's own sample whichever part drew it.
//
//   <bsdf type="blendbsdf">
//       <float name="weight" value="0.3"/>
//       <bsdf type="diffuse"/>
//       <bsdf type="roughconductor"/>
//   </bsdf>

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/bsdf/bsdf.h"
#include "core/bsdf/combined_traits.h"
#include "core/math/constants.h"
#include "core/registry/properties.h"
#include "core/texture/texture_parameter.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class BlendBsdf final : public Bsdf {
 public:
  explicit BlendBsdf(const Properties& props) : weight_(read_fraction(props, "weight")) {
    const auto nested = props.children<Bsdf>("bsdf");
    if (nested.size() != 2)
      throw SceneError(props.where(), "bsdf 'blendbsdf' takes two nested bsdfs, not " + std::to_string(nested.size()));
    first_ = nested[0];
    second_ = nested[1];
    traits_.emplace(*first_, *second_);
  }

  uint32_t lobes() const override { return traits_->lobes; }
  bool reads_tangents() const override { return traits_->reads_tangents; }
  bool renders_spectral() const override { return traits_->renders_spectral; }
  bool disperses() const override { return traits_->disperses; }

  Color eval(const BsdfContext& ctx, Vec3 wo, Vec3 wi) const override { return eval_with(weight(ctx), ctx, wo, wi); }

  float pdf(const BsdfContext& ctx, Vec3 wo, Vec3 wi) const override { return pdf_with(weight(ctx), ctx, wo, wi); }

  std::optional<BsdfSample> sample(const BsdfContext& ctx, Vec3 wo, float u_lobe, Vec2 u) const override {
    const float w = weight(ctx);
    const bool second = u_lobe >= 1 - w;
    const float chance = second ? w : 1 - w;
    const float u_rest = std::min((second ? u_lobe - (1 - w) : u_lobe) / chance, kOneMinusEpsilon);
    auto s = (second ? second_ : first_)->sample(ctx, wo, u_rest, u);
    if (!s) return std::nullopt;
    if (s->is_delta()) {
      // The other part has no delta in this direction to add (or, if it has
      // the same one, picking either by its chance keeps the mean).
      s->f *= chance;
      s->pdf *= chance;
      return s;
    }
    s->f = eval_with(w, ctx, wo, s->wi);
    s->pdf = pdf_with(w, ctx, wo, s->wi);
    if (!(s->pdf > 0)) return std::nullopt;
    return s;
  }

  Color albedo(const BsdfContext& ctx, Vec3 wo) const override {
    const float w = weight(ctx);
    return first_->albedo(ctx, wo) * (1 - w) + second_->albedo(ctx, wo) * w;
  }

 private:
  float weight(const BsdfContext& ctx) const { return eval_fraction(*weight_, ctx.uv, 0.5f); }

  // With the weight w at the point, read once per call.
  Color eval_with(float w, const BsdfContext& ctx, Vec3 wo, Vec3 wi) const {
    Color f;
    if (w < 1) f += first_->eval(ctx, wo, wi) * (1 - w);
    if (w > 0) f += second_->eval(ctx, wo, wi) * w;
    return f;
  }

  float pdf_with(float w, const BsdfContext& ctx, Vec3 wo, Vec3 wi) const {
    float p = 0;
    if (w < 1) p += first_->pdf(ctx, wo, wi) * (1 - w);
    if (w > 0) p += second_->pdf(ctx, wo, wi) * w;
    return p;
  }

  std::shared_ptr<Texture> weight_;
  std::shared_ptr<Bsdf> first_, second_;
  std::optional<CombinedTraits> traits_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(BlendBsdf, "bsdf", "blendbsdf",
                         {{"weight", ParamType::Texture, "0.5",
                           "share of the second nested bsdf (0: the first alone, 1: the second alone)"}},
                         {"bsdf"});

}  // namespace caustica
