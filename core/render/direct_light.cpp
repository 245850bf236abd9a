#include "core/render/direct_light.h"

#include "core/render/mis.h"
#include "core/scene/scene.h"

namespace caustica {

Color sample_direct_light(const Scene& scene, const SurfaceInteraction& si, const SurfaceBsdf& bsdf, Vec3 wo,
                          float u_select, Vec2 u_light, float n_light, float n_bsdf) {
  const auto choice = scene.light_selection().sample(u_select);
  if (!choice) return {};
  const ReferencePoint ref{si.p, si.p_error, si.ng};
  const auto ls = choice->emitter->sample_Li(ref, u_light);
  if (!ls || ls->pdf <= 0 || ls->Li.is_black()) return {};
  const Color f = bsdf.eval(wo, ls->wi) * abs_dot(ls->wi, si.shading.n);
  if (f.is_black()) return {};
  const Ray shadow = ls->is_infinite ? si.spawn(ls->wi) : si.spawn_to(ls->p, ls->p_error, ls->n);
  if (scene.occluded(shadow)) return {};
  const float pdf_light = choice->pmf * ls->pdf;
  const float weight = ls->is_delta ? 1 : power_heuristic(n_light, pdf_light, n_bsdf, bsdf.pdf(wo, ls->wi));
  return f * ls->Li * (weight / pdf_light);
}

float bsdf_sample_mis_weight(const Scene& scene, const Emitter& emitter, const ReferencePoint& from, Vec3 wi,
                             float bsdf_pdf, const SurfaceInteraction& on_light, float n_light, float n_bsdf) {
  const float pdf_light = scene.light_selection().pmf(&emitter) * emitter.pdf_Li(from, wi, on_light);
  return power_heuristic(n_bsdf, bsdf_pdf, n_light, pdf_light);
}

}  // namespace caustica
