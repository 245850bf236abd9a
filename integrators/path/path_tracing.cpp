#include "integrators/path/path_tracing.h"

#include <algorithm>

#include "core/render/direct_light.h"
#include "core/scene/scene.h"

namespace caustica {

Color trace_path(const Scene& scene, Ray ray, Sampler& sampler, const PathSettings& settings,
                 const CausticEstimator* caustics) {
  const auto& [max_depth, rr_depth, rr_max_survival, hide_emitters] = settings;
  if (max_depth == 0) return {};
  Color L, beta(1);
  float eta_scale = 1;
  bool specular = true;  // the camera ray counts as a specular "bounce"
  // The caustic estimator has the light this path finds next when the path
  // left its last non-delta vertex (where it gathered) by a non-delta
  // bounce, and only delta bounces followed.
  bool gathered = false;
  int delta_bounces_since = 0;
  float prev_pdf = 0;
  SurfaceInteraction prev;
  for (int64_t depth = 0;; ++depth) {
    const auto si = scene.intersect(ray);
    const bool show = (depth > 0 || !hide_emitters) && !(gathered && delta_bounces_since > 0);
    if (!si) {
      for (const Emitter* env : scene.infinite_emitters()) {
        const Color Le = env->Le_infinite(ray.d);
        if (!show || Le.is_black()) continue;
        const float w = specular ? 1 : bsdf_sample_mis_weight(scene, *env, prev, ray.d, prev_pdf, SurfaceInteraction{});
        L += beta * Le * w;
      }
      break;
    }
    if (const Emitter* emitter = si->shape->emitter(); emitter && show) {
      const Color Le = emitter->L(*si, -ray.d);
      if (!Le.is_black()) {
        const float w = specular ? 1 : bsdf_sample_mis_weight(scene, *emitter, prev, ray.d, prev_pdf, *si);
        L += beta * Le * w;
      }
    }
    if (max_depth >= 0 && depth + 1 >= max_depth) break;

    const SurfaceBsdf bsdf(*si->shape->bsdf(), *si, TransportMode::Radiance);
    const Vec3 wo = -ray.d;
    const float u_select = sampler.next_1d();
    const Vec2 u_light = sampler.next_2d();
    const bool non_delta = bsdf.lobes() & ~kDelta;
    if (non_delta) L += beta * sample_direct_light(scene, *si, bsdf, wo, u_select, u_light);
    if (non_delta && caustics) L += beta * caustics->estimate(*si, bsdf, wo, depth + 1);

    const float u_lobe = sampler.next_1d();
    const auto bs = bsdf.sample(wo, u_lobe, sampler.next_2d());
    if (!bs) break;
    beta *= bs->f * (abs_dot(bs->wi, si->shading.n) / bs->pdf);
    if (bs->is_transmission()) eta_scale *= bs->eta * bs->eta;
    specular = bs->is_delta();
    if (caustics && !specular) {
      gathered = true;
      delta_bounces_since = 0;
    } else if (gathered) {
      ++delta_bounces_since;
    }
    prev_pdf = bs->pdf;
    prev = *si;
    ray = si->spawn(bs->wi);

    if (depth + 1 >= rr_depth) {
      const float q = std::min(beta.max_component() * eta_scale, rr_max_survival);
      if (!(sampler.next_1d() < q)) break;
      beta *= 1 / q;
    }
  }
  return L;
}

}  // namespace caustica
