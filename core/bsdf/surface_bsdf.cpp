#include "core/bsdf/surface_bsdf.h"

#include <cmath>

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

// Reflection or transmission as the geometry sees it must match what the
// shading frame says, or a path could cross a surface through a reflection
// lobe (or bounce off it through a transmission lobe).
bool sides_agree(Vec3 wo_world, Vec3 wi_world, Vec3 wo, Vec3 wi, Vec3 ng) {
  const bool geometric_reflection = dot(wo_world, ng) * dot(wi_world, ng) > 0;
  return geometric_reflection == same_hemisphere(wo, wi);
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

float SurfaceBsdf::shading_correction(Vec3 wo_world, Vec3 wi_world) const {
  if (ctx_.mode == TransportMode::Radiance) return 1;
  const float num = abs_dot(wo_world, frame_.n) * abs_dot(wi_world, ng_);
  const float den = abs_dot(wo_world, ng_) * abs_dot(wi_world, frame_.n);
  return den == 0 ? 0 : num / den;
}

std::optional<SurfaceBsdf::LocalPair> SurfaceBsdf::local_pair(Vec3 wo_world, Vec3 wi_world) const {
  const Vec3 wo = frame_.to_local(wo_world), wi = frame_.to_local(wi_world);
  // Both tests are symmetric in the two directions.
  if (wo.z == 0 || wi.z == 0 || !sides_agree(wo_world, wi_world, wo, wi, ng_)) return std::nullopt;
  return LocalPair{wo, wi};
}

Color SurfaceBsdf::eval(Vec3 wo_world, Vec3 wi_world) const {
  const auto w = local_pair(wo_world, wi_world);
  if (!w) return {};
  return bsdf_->eval(ctx_, w->wo, w->wi) * shading_correction(wo_world, wi_world);
}

float SurfaceBsdf::pdf(Vec3 wo_world, Vec3 wi_world) const {
  const auto w = local_pair(wo_world, wi_world);
  return w ? bsdf_->pdf(ctx_, w->wo, w->wi) : 0;
}

SurfaceBsdf::EvalPdf SurfaceBsdf::eval_and_pdf(Vec3 wo_world, Vec3 wi_world) const {
  const auto w = local_pair(wo_world, wi_world);
  if (!w) return {{}, 0};
  return {bsdf_->eval(ctx_, w->wo, w->wi) * shading_correction(wo_world, wi_world), bsdf_->pdf(ctx_, w->wo, w->wi)};
}

SurfaceBsdf::PdfPair SurfaceBsdf::pdfs(Vec3 wo_world, Vec3 wi_world) const {
  const auto w = local_pair(wo_world, wi_world);
  if (!w) return {0, 0};
  return {bsdf_->pdf(ctx_, w->wo, w->wi), bsdf_->pdf(ctx_, w->wi, w->wo)};
}

SurfaceBsdf::EvalPdfs SurfaceBsdf::eval_and_pdfs(Vec3 wo_world, Vec3 wi_world) const {
  const auto w = local_pair(wo_world, wi_world);
  if (!w) return {{}, {0, 0}};
  return {bsdf_->eval(ctx_, w->wo, w->wi) * shading_correction(wo_world, wi_world),
          {bsdf_->pdf(ctx_, w->wo, w->wi), bsdf_->pdf(ctx_, w->wi, w->wo)}};
}

std::optional<BsdfSample> SurfaceBsdf::sample(Vec3 wo_world, float u_lobe, Vec2 u) const {
  const Vec3 wo = frame_.to_local(wo_world);
  if (wo.z == 0) return std::nullopt;
  auto s = bsdf_->sample(ctx_, wo, u_lobe, u);
  if (!s || s->pdf <= 0 || !(s->pdf < kInfinity) || s->f.is_black() || s->wi.z == 0) return std::nullopt;
  const Vec3 wi_world = frame_.to_world(s->wi);
  if (!sides_agree(wo_world, wi_world, wo, s->wi, ng_)) return std::nullopt;
  s->f *= shading_correction(wo_world, wi_world);
  s->wi = wi_world;
  return s;
}

}  // namespace caustica
