#include "core/transport/direct_light_in_media.h"

#include "core/media/medium.h"
#include "core/render/direct_light.h"
#include "core/scene/scene.h"
#include "core/transport/medium_crossing.h"
#include "core/transport/shadow_transmittance.h"

namespace caustica {

Color sample_direct_light_in_media(const Scene& scene, const SurfaceInteraction& si, const SurfaceBsdf& bsdf, Vec3 wo,
                                   const Medium* arrived_in, Sampler& sampler, float u_select, Vec2 u_light,
                                   float n_bsdf, const ScatterDensity* density) {
  const auto light = choose_light(scene, {si.p, si.p_error, si.ng, si.time}, u_select, u_light);
  if (!light) return {};
  const LiSample& ls = light->ls;
  const auto [bsdf_f, bsdf_pdf] = bsdf.eval_and_pdf(wo, ls.wi);
  const Color f = bsdf_f * abs_dot(ls.wi, si.shading.n);
  if (f.is_black()) return {};
  const Color tr = shadow_transmittance(scene, shadow_ray(si, ls), medium_after(si, arrived_in, ls.wi), sampler);
  if (tr.is_black()) return {};
  return f * tr * ls.Li * (light->mis_weight(scatter_pdf(density, ls.wi, bsdf_pdf), 1, n_bsdf) / light->pdf);
}

Color sample_direct_light_at_medium_point(const Scene& scene, Vec3 p, float time, const Medium& medium, Vec3 wo,
                                          Sampler& sampler, float u_select, Vec2 u_light) {
  const auto light = choose_light(scene, {p, {}, {}, time}, u_select, u_light);
  if (!light) return {};
  const LiSample& ls = light->ls;
  const float phase = medium.phase().eval(wo, ls.wi);
  if (!(phase > 0)) return {};
  // A point in a medium has no error to step off: the ray leaves from it.
  SurfaceInteraction at;
  at.p = p;
  at.time = time;
  const Ray shadow = shadow_ray(at, ls);
  const Color tr = shadow_transmittance(scene, shadow, &medium, sampler);
  if (tr.is_black()) return {};
  return tr * ls.Li * (phase * light->mis_weight(phase) / light->pdf);
}

}  // namespace caustica
