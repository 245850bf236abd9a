#include "core/render/direct_light.h"

#include "core/lights/spectral_emission.h"
#include "core/scene/scene.h"

namespace caustica {

std::optional<ChosenLight> choose_light(const Scene& scene, const ReferencePoint& ref, float u_select, Vec2 u_light) {
  const LightSelection& lights = scene.light_selection();
  const auto choice = scene.features().light_tree ? lights.sample(u_select, ref) : lights.sample(u_select);
  if (!choice) return std::nullopt;
  const auto ls = choice->emitter->sample_Li(ref, u_light);
  if (!ls || ls->pdf <= 0 || ls->Li.is_black()) return std::nullopt;
  return ChosenLight{*ls, choice->pmf * ls->pdf, choice->emitter};
}

Color sample_direct_light(const Scene& scene, const SurfaceInteraction& si, const SurfaceBsdf& bsdf, Vec3 wo,
                          float u_select, Vec2 u_light, float n_light, float n_bsdf, const Wavelengths* wavelengths,
                          const ScatterDensity* density) {
  const auto light = choose_light(scene, {si.p, si.p_error, si.ng, si.time}, u_select, u_light);
  if (!light) return {};
  const LiSample& ls = light->ls;
  const auto [bsdf_f, bsdf_pdf] = bsdf.eval_and_pdf(wo, ls.wi);
  const Color f = bsdf_f * abs_dot(ls.wi, si.shading.n);
  if (f.is_black()) return {};
  if (scene.occluded(shadow_ray(si, ls))) return {};
  return f * emission_for(*light->emitter, ls.Li, wavelengths) *
         (light->mis_weight(scatter_pdf(density, ls.wi, bsdf_pdf), n_light, n_bsdf) / light->pdf);
}

float bsdf_sample_mis_weight(const Scene& scene, const Emitter& emitter, const ReferencePoint& from, Vec3 wi,
                             float bsdf_pdf, const SurfaceInteraction& on_light, float n_light, float n_bsdf) {
  const LightSelection& lights = scene.light_selection();
  const float pmf = scene.features().light_tree ? lights.pmf(&emitter, from) : lights.pmf(&emitter);
  const float pdf_light = pmf * emitter.pdf_Li(from, wi, on_light);
  return power_heuristic(n_bsdf, bsdf_pdf, n_light, pdf_light);
}

}  // namespace caustica
