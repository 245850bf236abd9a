// sppm: stochastic progressive photon mapping (Hachisuka and Jensen 2009),
// the consistent method for scenes where caustics dominate. Every pass is
// one iteration: a round of photons is traced (all indirect light), then
// every pixel traces a camera ray through delta bounces to its visible
// point, adds the emission it met and next-event estimation there, and
// gathers the photons within its own radius. Each pixel keeps its photon
// statistics: N <- N + alpha M, R <- R sqrt(N_new / (N + M)) and
// tau <- (tau + Phi) R_new^2 / R^2, so its radius shrinks where photons are
// dense and the estimate converges as iterations add up. The image is
// D / n + tau / (n photons pi R^2) per pixel after n iterations, which
// enters the film once the iterations are done; the filter only places the
// camera rays. The camera walk through delta bounces has the walks'
// Russian roulette. Through participating media the camera walk also
// passes the scattering events it samples, adding direct light at each
// (weighed against the phase function's sample that continues the walk),
// and photons scatter in media but are kept on surfaces only: light
// scattered in a medium reaches the image through the surface its
// phase-sampled continuation finds, and each photon counts what it carries
// to a surface after scattering anywhere.
// In spectral mode each iteration draws one set of wavelengths
// (pass_wavelengths) that its photons and camera paths share, since a
// photon's power must meet the BSDF at its own wavelengths; the passes'
// sets spread evenly over the spectrum. In a moving scene they share the
// iteration's time (pass_time) the same way, so that photons land where
// the scene stands when the camera paths gather them.
// Photon rounds and the camera pass run in parallel and are deterministic
// for a seed.
//
// max_depth limits the whole path, a photon's segments included; rr_depth
// counts a photon path's vertices before Russian roulette may end it. Its
// default is 1, not the 5 of the other integrators: a photon then survives
// each bounce with about the probability its power would have kept, so
// photons carry about equal power and none is traced on for the little it
// still carries. At equal passes that cost up to 1.5x the relative MSE
// (less in fog) and saved 25 to 38 % of the time: relMSE x time 0.65 to
// 1.01 on the Cornell boxes measured (docs/performance.md).
//
//   <integrator type="sppm"><integer name="photons" value="200000"/></integrator>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "core/lights/spectral_emission.h"
#include "core/math/constants.h"
#include "core/registry/properties.h"
#include "core/render/camera_sample.h"
#include "core/render/direct_light.h"
#include "core/render/iterative_integrator.h"
#include "core/render/pass_time.h"
#include "core/render/path_settings.h"
#include "core/render/sample_wavelengths.h"
#include "core/scene/scene.h"
#include "core/transport/direct_light_in_media.h"
#include "core/transport/emission.h"
#include "core/transport/random_walk.h"
#include "integrators/photon/photon_density.h"
#include "integrators/photon/photon_settings.h"
#include "integrators/photon/photon_tracing.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

struct PixelState {
  Color direct;  // emission met and next-event estimates, summed over iterations
  Color tau;     // photon flux gathered, rescaled with the radius
  double n = 0;  // photons kept
  float radius = 0;
};

// A camera walk through delta bounces to the pixel's visible point: the
// emission it meets on the way, next-event estimation there (weight one, as
// no BSDF sample follows to share it with) and the photons within the
// pixel's radius.
class VisiblePoint {
 public:
  // With `wavelengths` (spectral mode) what it adds is at them.
  VisiblePoint(const Scene& scene, const PhotonMap& map, Sampler& sampler, const PathSettings& settings,
               const PixelState& px, const Wavelengths* wavelengths)
      : scene_(scene), map_(map), sampler_(sampler), settings_(settings), px_(px), wavelengths_(wavelengths) {}

  WalkAction at_vertex(const WalkVertex& v) {
    if (v.segments > 1 || !settings_.hide_emitters)
      emission_at_surface(scene_, v.si, v.wo, v.arrival, {}, [&](const Emitter& e, Color Le, float w) {
        direct += v.beta * emission_for(e, Le, wavelengths_) * w;
      });
    if (v.last) return WalkAction::Stop;
    if (!(v.bsdf.lobes() & ~kDelta)) return WalkAction::Continue;
    const float u_select = sampler_.next_1d();
    const Vec2 u_light = sampler_.next_2d();
    direct += v.beta *
              (scene_.features().medium_walk
                   ? sample_direct_light_in_media(scene_, v.si, v.bsdf, v.wo, v.medium, sampler_, u_select, u_light, 0)
                   : sample_direct_light(scene_, v.si, v.bsdf, v.wo, u_select, u_light, 1, 0, wavelengths_));
    const PhotonGather g = gather_photons(map_, px_.radius, v.si, v.bsdf, v.wo, v.segments, settings_.max_depth);
    flux = v.beta * g.flux;
    photons = double(g.count);
    return WalkAction::Stop;
  }

  void escaped(const WalkEscape& e) {
    if (e.segments > 1 || !settings_.hide_emitters)
      emission_from_environment(scene_, e.ray.d, e.ray.time, e.arrival, {},
                                [&](const Emitter& emitter, Color Le, float w) {
                                  direct += e.beta * emission_for(emitter, Le, wavelengths_) * w;
                                });
  }

  WalkAction scattered(const BsdfSample&) { return WalkAction::Continue; }

  WalkAction at_medium_vertex(const MediumVertex& v) {
    if (v.last) return WalkAction::Stop;
    const float u_select = sampler_.next_1d();
    const Vec2 u_light = sampler_.next_2d();
    if (v.medium.sample_emitters())
      direct += v.beta *
                sample_direct_light_at_medium_point(scene_, v.p, v.time, v.medium, v.wo, sampler_, u_select, u_light);
    return WalkAction::Continue;
  }

  WalkAction scattered_in_medium(const PhaseSample&) { return WalkAction::Continue; }

  Color direct;        // emission met and next-event estimates
  Color flux;          // the photons' contribution, times the path's weight
  double photons = 0;  // how many were found

 private:
  const Scene& scene_;
  const PhotonMap& map_;
  Sampler& sampler_;
  const PathSettings& settings_;
  const PixelState& px_;
  const Wavelengths* wavelengths_;
};

class StochasticProgressivePhotonMapping;

// One render's per-pixel statistics.
class SppmPixels final : public IterationState {
 public:
  SppmPixels(const StochasticProgressivePhotonMapping& settings, const Scene& scene, uint64_t seed);
  bool iterate(uint64_t iteration, const std::atomic<bool>* stop) override;
  Color estimate(Vec2i pixel) const override;
  // The radii's root mean square over the pixels: the trace of the schedule.
  std::string summary() const override;

 private:
  void iterate_pixel(const PhotonMap& map, Sampler& sampler, Vec2i pixel, uint64_t iteration, std::optional<float> time,
                     const Wavelengths* wavelengths);

  const StochasticProgressivePhotonMapping& settings_;
  const Scene& scene_;
  uint64_t seed_;
  int width_;
  std::vector<PixelState> pixels_;
  uint64_t iterations_ = 0;
  // Kept between iterations, so that their memory is reused.
  TracedPhotons traced_;
  PhotonMap map_;
};

class StochasticProgressivePhotonMapping final : public IterativeIntegrator {
 public:
  explicit StochasticProgressivePhotonMapping(const Properties& props)
      : settings_(read_path_settings(props)), photon_(read_photon_settings(props)) {}

  std::unique_ptr<IterationState> begin(const Scene& scene, uint64_t seed) const override {
    return std::make_unique<SppmPixels>(*this, scene, seed);
  }

  bool renders_media() const override { return true; }
  bool renders_spectral() const override { return true; }
  bool renders_motion() const override { return true; }

  std::string plan(const Scene& scene) const override {
    return std::string("sppm: ") + std::to_string(photon_.photons) +
           " photons per iteration carry all indirect light; emission and next-event estimation at each "
           "pixel's visible point" +
           (scene.features().media ? "; media: the camera walk passes scattering events (direct light at each), "
                                     "photons scatter in them and are kept on surfaces only"
                                   : "") +
           (scene.features().spectral ? "; spectral: each iteration's photons and camera paths share its wavelengths"
                                      : "") +
           (scene.features().motion ? "; motion: each iteration's photons and camera paths share its time" : "");
  }

 private:
  friend class SppmPixels;
  PathSettings settings_;
  PhotonSettings photon_;
};

SppmPixels::SppmPixels(const StochasticProgressivePhotonMapping& settings, const Scene& scene, uint64_t seed)
    : settings_(settings), scene_(scene), seed_(seed), width_(scene.sensor().film()->width()) {
  const float r0 = initial_radius(scene, settings.photon_);
  pixels_.assign(size_t(width_) * scene.sensor().film()->height(), PixelState{{}, {}, 0, r0});
}

bool SppmPixels::iterate(uint64_t iteration, const std::atomic<bool>* stop) {
  float max_radius = 0;
  for (const PixelState& px : pixels_) max_radius = std::max(max_radius, px.radius);
  std::optional<Wavelengths> wavelengths;
  if (scene_.features().spectral) wavelengths = pass_wavelengths(iteration, seed_);
  const Wavelengths* w = wavelengths ? &*wavelengths : nullptr;
  std::optional<float> time;
  if (scene_.features().motion) time = pass_time(iteration, seed_);
  if (!trace_photons(scene_, PhotonPaths::Indirect, uint64_t(settings_.photon_.photons), iteration, seed_,
                     time.value_or(0), settings_.settings_, traced_, stop, w))
    return false;
  map_.build(traced_.all, max_radius);
  const PhotonMap& map = map_;
  const int height = int(pixels_.size() / size_t(width_));
  tbb::parallel_for(0, height, [&](int y) {
    auto sampler = scene_.sensor().sampler()->clone();
    for (int x = 0; x < width_; ++x) iterate_pixel(map, *sampler, {x, y}, iteration, time, w);
  });
  ++iterations_;
  return true;
}

std::string SppmPixels::summary() const {
  double sum = 0;
  for (const PixelState& px : pixels_) sum += double(px.radius) * px.radius;
  char radius[32];
  std::snprintf(radius, sizeof radius, "%.6g", std::sqrt(sum / double(pixels_.size())));
  return "iterations=" + std::to_string(iterations_) + ", rms radius=" + radius;
}

// D / n + tau / (n photons pi R^2).
Color SppmPixels::estimate(Vec2i pixel) const {
  const PixelState& px = pixels_[size_t(pixel.y) * width_ + pixel.x];
  const double emitted = double(iterations_) * double(settings_.photon_.photons);
  return px.direct / float(iterations_) + px.tau / float(emitted * kPi * double(px.radius) * double(px.radius));
}

// The camera path's estimates enter the pixel in RGB, converted at its own
// copy of the iteration's wavelengths (which dispersion may terminate).
void SppmPixels::iterate_pixel(const PhotonMap& map, Sampler& sampler, Vec2i pixel, uint64_t iteration,
                               std::optional<float> time, const Wavelengths* iteration_wavelengths) {
  PixelState& px = pixels_[size_t(pixel.y) * width_ + pixel.x];
  const CameraSample cs = sample_camera_ray(scene_, sampler, pixel, iteration, seed_, time);
  SampleWavelengths w(iteration_wavelengths);
  VisiblePoint visible(scene_, map, sampler, settings_.settings_, px, w.get());
  random_walk(scene_, cs.ray, Color(1), TransportMode::Radiance, camera_walk_limits(settings_.settings_), sampler,
              visible, scene_.sensor().medium(), w.get());
  px.direct += w.to_rgb(visible.direct);
  visible.flux = w.to_rgb(visible.flux);
  if (visible.photons > 0) {
    const double n_new = px.n + settings_.photon_.alpha * visible.photons;
    const double shrink2 = n_new / (px.n + visible.photons);  // R_new^2 / R^2
    px.tau = (px.tau + visible.flux) * float(shrink2);
    px.radius = float(px.radius * std::sqrt(shrink2));
    px.n = n_new;
  }
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(
    StochasticProgressivePhotonMapping, "integrator", "sppm",
    path_settings_params({{"photons", ParamType::Integer, "100000", "photons traced per iteration"},
                          {"radius", ParamType::Float, "0",
                           "initial radius; 0 for 1/200 of the scene's bounding-box diagonal"},
                          {"alpha", ParamType::Float, "0.7", "fraction of new photons kept per iteration, in (0, 1)"}},
                         1),
    {});

}  // namespace caustica
