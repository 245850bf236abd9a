#pragma once

#include <cmath>
#include <memory>
#include <optional>

#include "core/bsdf/bsdf.h"
#include "core/registry/properties.h"

namespace caustica {

// A wrapper that evaluates a nested BSDF in a shading frame of its own (bump
// and normal mapping): subclasses say where the frame is, in the local
// frame of the unperturbed surface. Directions on the same side of one
// surface but on opposite sides of the other carry nothing, so no light
// leaks through the relief. The perturbed normal is the shading normal:
// the cosine of the direction light arrives from (wi in radiance
// transport, wo in importance) is taken about it, as pbrt and Mitsuba
// take it, so eval and sample scale the nested value by that cosine over
// the one the integrator multiplies by, about the unperturbed normal.
class PerturbedFrameBsdf : public Bsdf {
 public:
  // Takes the nested bsdf the wrapper's element must hold.
  explicit PerturbedFrameBsdf(const Properties& props) : nested_(props.child<Bsdf>("bsdf")) {
    if (!nested_) throw SceneError(props.where(), "bsdf '" + props.info().name + "' takes one nested bsdf");
  }

  uint32_t lobes() const override { return nested_->lobes(); }
  bool renders_spectral() const override { return nested_->renders_spectral(); }
  bool disperses() const override { return nested_->disperses(); }

  Color eval(const BsdfContext& ctx, Vec3 wo, Vec3 wi) const override {
    const Frame f = frame(ctx);
    const Vec3 wo_p = f.to_local(wo), wi_p = f.to_local(wi);
    if (!sides_agree(wo, wi, wo_p, wi_p)) return {};
    return nested_->eval(nested_context(ctx, f), wo_p, wi_p) * cosine_ratio(ctx, wo, wi, wo_p, wi_p);
  }

  float pdf(const BsdfContext& ctx, Vec3 wo, Vec3 wi) const override {
    const Frame f = frame(ctx);
    const Vec3 wo_p = f.to_local(wo), wi_p = f.to_local(wi);
    if (!sides_agree(wo, wi, wo_p, wi_p)) return 0;
    return nested_->pdf(nested_context(ctx, f), wo_p, wi_p);
  }

  std::optional<BsdfSample> sample(const BsdfContext& ctx, Vec3 wo, float u_lobe, Vec2 u) const override {
    const Frame f = frame(ctx);
    const Vec3 wo_p = f.to_local(wo);
    auto s = nested_->sample(nested_context(ctx, f), wo_p, u_lobe, u);
    if (!s) return std::nullopt;
    const Vec3 wi = f.to_world(s->wi);
    if (!sides_agree(wo, wi, wo_p, s->wi)) return std::nullopt;
    s->f *= cosine_ratio(ctx, wo, wi, wo_p, s->wi);
    s->wi = wi;
    return s;
  }

  Color albedo(const BsdfContext& ctx, Vec3 wo) const override {
    const Frame f = frame(ctx);
    return nested_->albedo(nested_context(ctx, f), f.to_local(wo));
  }

 protected:
  // The perturbed shading frame, in the local frame of the unperturbed one.
  virtual Frame frame(const BsdfContext& ctx) const = 0;

 private:
  // Reflection or transmission must mean the same about both surfaces.
  static bool sides_agree(Vec3 wo, Vec3 wi, Vec3 wo_p, Vec3 wi_p) {
    return wo.z * wo_p.z > 0 && wi.z * wi_p.z > 0 && same_hemisphere(wo, wi) == same_hemisphere(wo_p, wi_p);
  }

  // |cos| about the perturbed normal over |cos| about the unperturbed one,
  // of the direction light arrives from; 0 where the latter is 0.
  static float cosine_ratio(const BsdfContext& ctx, Vec3 wo, Vec3 wi, Vec3 wo_p, Vec3 wi_p) {
    const bool radiance = ctx.mode == TransportMode::Radiance;
    const float c = std::abs(radiance ? wi.z : wo.z), c_p = std::abs(radiance ? wi_p.z : wo_p.z);
    return c > 0 ? c_p / c : 0.0f;
  }

  static BsdfContext nested_context(const BsdfContext& ctx, const Frame& f) {
    BsdfContext out = ctx;
    out.dpdu = f.to_local(ctx.dpdu);
    out.dpdv = f.to_local(ctx.dpdv);
    return out;
  }

  std::shared_ptr<Bsdf> nested_;
};

}  // namespace caustica
