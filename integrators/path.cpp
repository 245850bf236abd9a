// path: unidirectional path tracing with next-event estimation. Every vertex
// samples an emitter and the BSDF, and both strategies are combined by
// multiple importance sampling (power heuristic).
//
// Parameters (core/render/path_settings.h)
//   max_depth         integer  -1     longest path in segments from the camera; -1 for no
//                                      limit, 0 renders black, 1 shows emitters only, 2 direct
//                                      light only
//   rr_depth          integer  5      depth from which Russian roulette may end paths
//   rr_max_survival   float    0.95   upper bound on the survival probability
//   hide_emitters     boolean  false  emitters seen directly by the camera appear black
//
// Russian roulette policy: from rr_depth on, a path survives with probability
// q = min(max_component(throughput) * eta_scale, rr_max_survival), and the
// survivors' throughput is divided by q, which keeps the estimator unbiased.
// eta_scale undoes the radiance scaling of refraction, so a path is not
// killed merely for having entered glass.
//
//   <integrator type="path"><integer name="max_depth" value="8"/></integrator>

#include <algorithm>

#include "core/bsdf/surface_bsdf.h"
#include "core/registry/properties.h"
#include "core/render/direct_light.h"
#include "core/render/path_settings.h"
#include "core/render/radiance_integrator.h"
#include "core/scene/scene.h"

namespace caustica {
namespace {

class PathIntegrator final : public RadianceIntegrator {
 public:
  explicit PathIntegrator(const Properties& props) : settings_(read_path_settings(props)) {}

  Color Li(const Scene& scene, Ray ray, Sampler& sampler) const override {
    const auto& [max_depth, rr_depth, rr_max_survival, hide_emitters] = settings_;
    if (max_depth == 0) return {};
    Color L, beta(1);
    float eta_scale = 1;
    bool specular = true;  // the camera ray counts as a specular "bounce"
    float prev_pdf = 0;
    SurfaceInteraction prev;
    for (int64_t depth = 0;; ++depth) {
      const auto si = scene.intersect(ray);
      const bool show = depth > 0 || !hide_emitters;
      if (!si) {
        for (const Emitter* env : scene.infinite_emitters()) {
          const Color Le = env->Le_infinite(ray.d);
          if (!show || Le.is_black()) continue;
          const float w =
              specular ? 1 : bsdf_sample_mis_weight(scene, *env, prev, ray.d, prev_pdf, SurfaceInteraction{});
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
      if (bsdf.lobes() & ~kDelta) L += beta * sample_direct_light(scene, *si, bsdf, wo, u_select, u_light);

      const float u_lobe = sampler.next_1d();
      const auto bs = bsdf.sample(wo, u_lobe, sampler.next_2d());
      if (!bs) break;
      beta *= bs->f * (abs_dot(bs->wi, si->shading.n) / bs->pdf);
      if (bs->is_transmission()) eta_scale *= bs->eta * bs->eta;
      specular = bs->is_delta();
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

  std::string describe() const override { return caustica::describe("path", settings_); }

 private:
  PathSettings settings_;
};

}  // namespace

CAUSTICA_REGISTER_PLUGIN(PathIntegrator, "integrator", "path", path_settings_params(), {});

}  // namespace caustica
