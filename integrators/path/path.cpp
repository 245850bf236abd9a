// path: unidirectional path tracing with next-event estimation. Every vertex
// samples an emitter and the BSDF, and both strategies are combined by
// multiple importance sampling (power heuristic).
//
// Russian roulette policy: from rr_depth on, a path survives with probability
// q = min(max_component(throughput) * eta_scale, rr_max_survival), and the
// survivors' throughput is divided by q, which keeps the estimator unbiased.
// eta_scale undoes the radiance scaling of refraction, so a path is not
// killed merely for having entered glass.
//
//   <integrator type="path"><integer name="max_depth" value="8"/></integrator>

#include "core/registry/properties.h"
#include "core/render/path_settings.h"
#include "core/render/pixel_integrator.h"
#include "core/scene/scene.h"
#include "integrators/path/path_tracing.h"

namespace caustica {
namespace {

class PathIntegrator final : public RadianceIntegrator {
 public:
  explicit PathIntegrator(const Properties& props) : settings_(read_path_settings(props)) {}

  Color Li(const Scene& scene, Ray ray, Sampler& sampler) const override {
    return trace_path(scene, ray, sampler, settings_);
  }

  std::string plan(const Scene& scene) const override {
    const SceneFeatures& f = scene.features();
    return std::string("path: next-event estimation and BSDF sampling combined by MIS") +
           (f.environment_lights ? "" : "; no environment, escaping paths end at once") +
           (f.caustic_paths ? "; caustics only by BSDF sampling (noisy)" : "");
  }

 private:
  PathSettings settings_;
};

}  // namespace

CAUSTICA_REGISTER_PLUGIN(PathIntegrator, "integrator", "path", path_settings_params(), {});

}  // namespace caustica
