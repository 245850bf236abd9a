// ptracer: light tracing (particle tracing). Each sample traces one path
// from an emitter (chosen by power) with importance-mode BSDFs and joins
// every vertex to the camera, splatting the contribution where it lands.
// A sample's light path comes from its pixel's light-path stream. It renders caustics seen
// directly well, but nothing seen through a delta surface (a mirror or
// smooth glass between the camera and the first diffuse or glossy surface):
// such paths cannot be joined to a pinhole.
//
// max_depth counts a path's segments from the camera, as for path; rr_depth
// counts the light path's vertices after the emitter before Russian roulette
// may end it. Through media the light path scatters in them too, and every
// scattering event is joined to the camera like a surface, its phase
// function in place of a BSDF and the transmittance to the lens in place
// of visibility.
//
//   <integrator type="ptracer"><integer name="max_depth" value="8"/></integrator>

#include <vector>

#include "core/registry/properties.h"
#include "core/render/camera_sample.h"
#include "core/render/light_path_integrator.h"
#include "core/render/path_settings.h"
#include "core/render/sample_wavelengths.h"
#include "core/scene/scene.h"
#include "integrators/bidirectional/camera_connection.h"
#include "integrators/bidirectional/subpath.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class ParticleTracer final : public LightPathIntegrator {
 public:
  explicit ParticleTracer(const Properties& props) : settings_(read_path_settings(props)) {}

  float sample(const Scene& scene, SampleId id, uint64_t seed, Sampler& sampler, std::span<float> out,
               SplatList& splats) const override {
    std::fill(out.begin(), out.end(), 0.0f);
    sampler.start_sample(SampleKey::light_path(id.pixel), id.index, seed);
    thread_local std::vector<PathVertex> light;
    // In spectral mode the light path draws its wavelengths first.
    SampleWavelengths w(scene, sampler);
    const float time = sample_shutter_time(scene, sampler);
    trace_light_subpath(scene, sampler, time, settings_, light, w.get());
    for (int s = settings_.hide_emitters ? 2 : 1; s <= int(light.size()); ++s)
      if (const auto c = connect_to_camera(scene, light, s, sampler, w.get()))
        splats.add(c->raster, w.to_rgb(c->value));
    return 1;
  }

  bool renders_media() const override { return true; }
  bool renders_spectral() const override { return true; }
  bool renders_motion() const override { return true; }
  bool traces_all_light_from_lights() const override { return true; }

  std::string plan(const Scene& scene) const override {
    return std::string("ptracer: light paths joined to the camera") +
           (scene.features().lobes & kDelta ? "; surfaces seen through delta lobes stay black" : "") +
           (scene.features().media ? "; media: scattering events joined to the camera through the media between" : "");
  }

 private:
  PathSettings settings_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(ParticleTracer, "integrator", "ptracer", path_settings_params(), {});

}  // namespace caustica
