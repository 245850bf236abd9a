// path: unidirectional path tracing with next-event estimation. Every vertex
// samples an emitter and the BSDF, and both strategies are combined by
// multiple importance sampling (power heuristic).
//
// Russian roulette policy: from rr_depth on, a path whose
// t = max_component(throughput) * eta_scale has fallen below rr_threshold
// survives with probability q = min(t, rr_max_survival), and the
// survivors' throughput is divided by q, which keeps the estimator unbiased;
// paths at or above the threshold go on. eta_scale undoes the radiance
// scaling of refraction, so a path is not killed merely for having entered
// glass.
//
//   <integrator type="path"><integer name="max_depth" value="8"/></integrator>

#include "core/registry/properties.h"
#include "core/render/path_settings.h"
#include "core/render/pixel_integrator.h"
#include "core/render/sample_wavelengths.h"
#include "core/scene/scene.h"
#include "integrators/path/path_tracing.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class PathIntegrator : public RadianceIntegrator {
 public:
  explicit PathIntegrator(const Properties& props) : settings_(read_path_settings(props)) {}

  // In spectral mode each camera ray draws its wavelengths first.
  Color Li(const Scene& scene, Ray ray, Sampler& sampler) const override {
    SampleWavelengths w(scene, sampler);
    return w.to_rgb(trace_path(scene, ray, sampler, settings_, nullptr, w.get()));
  }

  bool renders_media() const override { return true; }
  bool renders_motion() const override { return true; }
  bool renders_spectral() const override { return true; }

  std::string plan(const Scene& scene) const override {
    const SceneFeatures& f = scene.features();
    return plugin_name() + ": next-event estimation and BSDF sampling combined by MIS" +
           (f.environment_lights ? "" : "; no environment, escaping paths end at once") +
           (f.caustic_paths ? "; caustics only by BSDF sampling (noisy)" : "") +
           (f.media ? "; media: free flights sampled, direct light at scattering events weighed against the phase "
                      "function"
                    : "; no media, the walk skips them") +
           (f.spectral ? "; spectral: three wavelengths per path, RGB lifted to spectra" : "");
  }

 private:
  PathSettings settings_;
};

// Mitsuba's name for its path tracer with media: the same integrator.
class VolpathIntegrator final : public PathIntegrator {
 public:
  using PathIntegrator::PathIntegrator;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(PathIntegrator, "integrator", "path", path_settings_params(), {});
CAUSTICA_REGISTER_PLUGIN(VolpathIntegrator, "integrator", "volpath", path_settings_params(), {});

}  // namespace caustica
