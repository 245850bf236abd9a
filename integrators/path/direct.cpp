// direct: direct illumination only (one bounce from the emitters to the camera).
// Emitter samples and BSDF samples are combined by multiple importance
// sampling (power heuristic, accounting for the number of each).
//
//   <integrator type="direct"><integer name="emitter_samples" value="4"/></integrator>

#include "core/bsdf/surface_bsdf.h"
#include "core/lights/spectral_emission.h"
#include "core/registry/properties.h"
#include "core/render/direct_light.h"
#include "core/render/pixel_integrator.h"
#include "core/render/sample_wavelengths.h"
#include "core/scene/scene.h"
#include "core/transport/emission.h"
#include "core/transport/random_walk.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

int64_t count(const Properties& props, const char* name) {
  const int64_t n = props.get_int_or(name, props.get_int("shading_samples"));
  if (n < 0) throw props.error(name, "must not be negative");
  return n;
}

class DirectIntegrator;

// The camera ray's one vertex: its emission, then emitter samples and BSDF
// samples, each BSDF sample looking for emission one segment further.
class DirectLight {
 public:
  // With `wavelengths` (spectral mode) L is at them.
  DirectLight(const Scene& scene, Sampler& sampler, const DirectIntegrator& settings, const Wavelengths* wavelengths);
  WalkAction at_vertex(const WalkVertex& v);
  void escaped(const WalkEscape& e);
  WalkAction scattered(const BsdfSample&) { return WalkAction::Stop; }

  Color L;

 private:
  const Scene& scene_;
  Sampler& sampler_;
  const DirectIntegrator& settings_;
  const Wavelengths* wavelengths_;
};

class DirectIntegrator final : public RadianceIntegrator {
 public:
  explicit DirectIntegrator(const Properties& props)
      : emitter_samples_(count(props, "emitter_samples")),
        bsdf_samples_(count(props, "bsdf_samples")),
        hide_emitters_(props.get_bool("hide_emitters")) {
    if (emitter_samples_ + bsdf_samples_ == 0)
      throw props.error("bsdf_samples", "emitter_samples + bsdf_samples must be positive");
  }

  // In spectral mode each camera ray draws its wavelengths first.
  Color Li(const Scene& scene, Ray ray, Sampler& sampler) const override {
    SampleWavelengths w(scene, sampler);
    DirectLight direct(scene, sampler, *this, w.get());
    random_walk(scene, ray, Color(1), TransportMode::Radiance, {1, {}}, sampler, direct, nullptr, w.get());
    return w.to_rgb(direct.L);
  }

  bool renders_spectral() const override { return true; }
  bool renders_motion() const override { return true; }

 private:
  friend class DirectLight;
  int64_t emitter_samples_, bsdf_samples_;
  bool hide_emitters_;
};

DirectLight::DirectLight(const Scene& scene, Sampler& sampler, const DirectIntegrator& settings,
                         const Wavelengths* wavelengths)
    : scene_(scene), sampler_(sampler), settings_(settings), wavelengths_(wavelengths) {}

WalkAction DirectLight::at_vertex(const WalkVertex& v) {
  if (!settings_.hide_emitters_)
    emission_at_surface(scene_, v.si, v.wo, v.arrival, {}, [&](const Emitter& e, Color Le, float w) {
      L += v.beta * emission_for(e, Le, wavelengths_) * w;
    });
  const MisCounts counts{float(settings_.emitter_samples_), float(settings_.bsdf_samples_)};
  if (v.bsdf.lobes() & ~kDelta)
    for (int64_t i = 0; i < settings_.emitter_samples_; ++i) {
      const float u_select = sampler_.next_1d();
      const Vec2 u_light = sampler_.next_2d();
      L += sample_direct_light(scene_, v.si, v.bsdf, v.wo, u_select, u_light, counts.n_light, counts.n_bsdf,
                               wavelengths_) *
           (1 / counts.n_light);
    }
  for (int64_t i = 0; i < settings_.bsdf_samples_; ++i) {
    const float u_lobe = sampler_.next_1d();
    const auto bs = v.bsdf.sample(v.wo, u_lobe, sampler_.next_2d());
    if (!bs) continue;
    const Color weight = bs->f * (abs_dot(bs->wi, v.si.shading.n) / (bs->pdf * counts.n_bsdf));
    const Arrival arrival = arrival_from(v.si, *bs);
    const auto add = [&](const Emitter& e, Color Le, float w) { L += weight * emission_for(e, Le, wavelengths_) * w; };
    if (const auto hit = scene_.intersect(v.si.spawn(bs->wi)))
      emission_at_surface(scene_, *hit, -bs->wi, arrival, counts, add);
    else
      emission_from_environment(scene_, bs->wi, arrival.from.time, arrival, counts, add);
  }
  return WalkAction::Stop;
}

void DirectLight::escaped(const WalkEscape& e) {
  if (!settings_.hide_emitters_)
    emission_from_environment(
        scene_, e.ray.d, e.ray.time, e.arrival, {},
        [&](const Emitter& emitter, Color Le, float w) { L += e.beta * emission_for(emitter, Le, wavelengths_) * w; });
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(
    DirectIntegrator, "integrator", "direct",
    {{"emitter_samples", ParamType::Integer, "1", "emitter samples per ray (if not given: shading_samples)"},
     {"bsdf_samples", ParamType::Integer, "1", "BSDF samples per ray (if not given: shading_samples)"},
     {"shading_samples", ParamType::Integer, "1", "default for both sample counts"},
     {"hide_emitters", ParamType::Boolean, "false", "hide directly visible emitters"}},
    {});

}  // namespace caustica
