// photon: path tracing for all light except caustics (light focused through
// mirrors or smooth glass onto a non-delta surface, L S+ D), which come
// from a caustic photon map instead; the path tracer leaves exactly those
// paths to it (integrators/path/path_tracing.h), so nothing is counted twice.
// Progressive (Knaus and Zwicker 2011): before every pass of
// samples_per_round samples per pixel, a new round of photons is traced and
// the gather radius shrinks as r_{i+1}^2 = r_i^2 (i + alpha) / (i + 1), so
// the image converges to the right answer as the rounds add up. When the
// scene cannot have caustic paths (SceneFeatures) no photon is traced and
// the integrator costs what path costs. In spectral mode a round's photons
// and the camera paths of its pass share the round's wavelengths
// (pass_wavelengths), so that photons meet BSDFs at their own wavelengths;
// in a moving scene they share the round's time (pass_time), so that
// photons land where the scene stands when the camera paths gather them.
//
// max_depth limits the whole path, a photon's segments included; rr_depth
// counts the vertices before Russian roulette on camera and photon paths
// alike.
//
//   <integrator type="photon"><integer name="photons" value="200000"/></integrator>

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "core/math/constants.h"
#include "core/registry/properties.h"
#include "core/render/pass_time.h"
#include "core/render/path_settings.h"
#include "core/render/pixel_integrator.h"
#include "core/render/sample_wavelengths.h"
#include "core/scene/scene.h"
#include "integrators/path/path_tracing.h"
#include "integrators/photon/photon_density.h"
#include "integrators/photon/photon_settings.h"
#include "integrators/photon/photon_tracing.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// Density estimation over a round's caustic photon map.
class CausticGather final : public CausticEstimator {
 public:
  CausticGather(const PhotonMap& map, uint64_t emitted, int64_t max_depth)
      : map_(&map), emitted_(emitted), max_depth_(max_depth) {}

  Color estimate(const SurfaceInteraction& si, const SurfaceBsdf& bsdf, Vec3 wo,
                 int64_t camera_segments) const override {
    const float r = map_->radius();
    return gather_photons(*map_, r, si, bsdf, wo, camera_segments, max_depth_).flux / (kPi * r * r * float(emitted_));
  }

 private:
  const PhotonMap* map_;
  uint64_t emitted_;
  int64_t max_depth_;
};

class PhotonIntegrator;

// One render's photon rounds: the map of the current pass's round, or
// nothing when the scene cannot have caustic paths.
class CausticRounds final : public PixelEstimator {
 public:
  CausticRounds(const PhotonIntegrator& settings, const Scene& scene, uint64_t seed);

  // Without photons there is nothing to refine between passes.
  uint32_t max_pass_samples() const override;
  bool begin_pass(const PassRange& range, const std::atomic<bool>* stop) override;
  std::optional<float> pass_time() const override { return round_time_; }
  void sample(Vec2i /*pixel*/, const Ray& ray, Sampler& sampler, std::span<float> out) const override;
  std::string summary() const override {
    if (!enabled_) return "(photon pass skipped)";
    char radius[32];
    std::snprintf(radius, sizeof radius, "%.6g", map_.radius());
    return "rounds=" + std::to_string(rounds_) + ", radius=" + radius;
  }

 private:
  const PhotonIntegrator& settings_;
  const Scene& scene_;
  uint64_t seed_;
  bool enabled_;
  float initial_radius_;
  std::optional<uint32_t> round_;
  std::optional<Wavelengths> round_wavelengths_;  // spectral mode, with photons
  std::optional<float> round_time_;               // moving scenes, with photons
  uint32_t rounds_ = 0;
  TracedPhotons traced_;  // kept between rounds, so that its memory is reused
  PhotonMap map_;
  std::optional<CausticGather> gather_;
};

class PhotonIntegrator final : public PixelIntegrator {
 public:
  explicit PhotonIntegrator(const Properties& props)
      : settings_(read_path_settings(props)),
        photon_(read_photon_settings(props)),
        samples_per_round_(props.get_int("samples_per_round")) {
    if (samples_per_round_ < 1 || samples_per_round_ > 1024)
      throw props.error("samples_per_round", "must be between 1 and 1024");
  }

  std::unique_ptr<PixelEstimator> estimator(const Scene& scene, uint64_t seed) const override {
    return std::make_unique<CausticRounds>(*this, scene, seed);
  }

  bool renders_media() const override { return true; }
  bool renders_spectral() const override { return true; }
  bool renders_motion() const override { return true; }

  std::string plan(const Scene& scene) const override {
    const std::string media = scene.features().media
                                  ? "; media: photons are kept on surfaces only, and paths scattered in a medium are "
                                    "path-traced"
                                  : "";
    if (!scene.features().caustic_paths)
      return std::string("photon: caustic photon pass skipped (") + scene.features().caustics_reason +
             "); path tracing alone, at path's cost" + media;
    return std::string("photon: ") + std::to_string(photon_.photons) + " caustic photons per round (" +
           scene.features().caustics_reason + "), path tracing for the rest" + media +
           (scene.features().spectral ? "; spectral: each round's photons and its pass's camera paths share its "
                                        "wavelengths"
                                      : "") +
           (scene.features().motion ? "; motion: each round's photons and its pass's camera paths share its time" : "");
  }

  std::string distributed_note() const override {
    return "each rank traces every photon round itself and gathers for its own share of the samples";
  }

 private:
  friend class CausticRounds;

  PathSettings settings_;
  PhotonSettings photon_;
  int64_t samples_per_round_;
};

CausticRounds::CausticRounds(const PhotonIntegrator& settings, const Scene& scene, uint64_t seed)
    : settings_(settings), scene_(scene), seed_(seed), enabled_(scene.features().caustic_paths) {
  initial_radius_ = initial_radius(scene, settings.photon_);
}

uint32_t CausticRounds::max_pass_samples() const { return enabled_ ? uint32_t(settings_.samples_per_round_) : 16; }

// A pass's round is its number in the schedule, so a sample's photons do
// not depend on where the render of its range began.
bool CausticRounds::begin_pass(const PassRange& range, const std::atomic<bool>* stop) {
  const uint32_t pass = range.pass;
  if (!enabled_ || round_ == pass) return true;
  const uint64_t photons = uint64_t(settings_.photon_.photons);
  if (scene_.features().spectral) round_wavelengths_ = pass_wavelengths(pass, seed_);
  if (scene_.features().motion) round_time_ = caustica::pass_time(pass, seed_);
  if (!trace_photons(scene_, PhotonPaths::Caustic, photons, pass, seed_, round_time_.value_or(0), settings_.settings_,
                     traced_, stop, round_wavelengths_ ? &*round_wavelengths_ : nullptr))
    return false;
  round_ = pass;
  ++rounds_;
  map_.build(traced_.all, round_radius(settings_.photon_, initial_radius_, pass));
  gather_.emplace(map_, photons, settings_.settings_.max_depth);
  return true;
}

// Without photons, spectral paths draw their own wavelengths, as path's do.
void CausticRounds::sample(Vec2i, const Ray& ray, Sampler& sampler, std::span<float> out) const {
  Color L;
  if (!enabled_) {
    SampleWavelengths w(scene_, sampler);
    L = w.to_rgb(trace_path(scene_, ray, sampler, settings_.settings_, nullptr, w.get()));
  } else {
    SampleWavelengths w(round_wavelengths_ ? &*round_wavelengths_ : nullptr);
    L = w.to_rgb(trace_path(scene_, ray, sampler, settings_.settings_, &*gather_, w.get()));
  }
  out[0] = L.r;
  out[1] = L.g;
  out[2] = L.b;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(
    PhotonIntegrator, "integrator", "photon",
    path_settings_params(
        {{"photons", ParamType::Integer, "100000", "photons traced per round"},
         {"radius", ParamType::Float, "0", "initial gather radius; 0 for 1/200 of the scene's bounding-box diagonal"},
         {"alpha", ParamType::Float, "0.7", "fraction of new photons kept per round (radius reduction), in (0, 1)"},
         {"samples_per_round", ParamType::Integer, "1", "samples per pixel per photon round"}}),
    {});

}  // namespace caustica
