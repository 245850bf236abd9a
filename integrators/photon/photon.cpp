// photon: path tracing for all light except caustics (light focused through
// mirrors or smooth glass onto a non-delta surface, L S+ D), which come
// from a caustic photon map instead; the path tracer leaves exactly those
// paths to it (integrators/path/path_tracing.h), so nothing is counted twice.
// Progressive (Knaus and Zwicker 2011): before every pass of
// samples_per_round samples per pixel, a new round of photons is traced and
// the gather radius shrinks as r_{i+1}^2 = r_i^2 (i + alpha) / (i + 1), so
// the image converges to the right answer as the rounds add up. When the
// scene cannot have caustic paths (SceneFeatures) no photon is traced and
// the integrator costs what path costs.
//
// Parameters (path length as in core/render/path_settings.h)
//   max_depth          integer  -1      longest path in segments, photon paths included
//   rr_depth           integer  5       vertices before Russian roulette (camera and photon paths)
//   rr_max_survival    float    0.95    upper bound on the survival probability
//   hide_emitters      boolean  false   emitters seen directly appear black
//   photons            integer  100000  photons traced per round
//   radius             float    0       initial gather radius; 0 for 1/200 of the scene's bounding-box diagonal
//   alpha              float    0.7     fraction of new photons kept per round, in (0, 1)
//   samples_per_round  integer  1       samples per pixel between photon rounds
//
//   <integrator type="photon"><integer name="photons" value="200000"/></integrator>

#include <cmath>
#include <optional>
#include <string>

#include "core/math/constants.h"
#include "core/registry/properties.h"
#include "core/render/path_settings.h"
#include "core/render/radiance_integrator.h"
#include "core/scene/scene.h"
#include "integrators/path/path_tracing.h"
#include "integrators/photon/photon_density.h"
#include "integrators/photon/photon_tracing.h"

namespace caustica {
namespace {

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

class PhotonIntegrator final : public RadianceIntegrator {
 public:
  explicit PhotonIntegrator(const Properties& props)
      : settings_(read_path_settings(props)),
        photons_(props.get_int("photons")),
        radius_(props.get_float("radius")),
        alpha_(props.get_float("alpha")),
        samples_per_round_(props.get_int("samples_per_round")) {
    if (photons_ < 1) throw props.error("photons", "must be at least 1");
    if (!(radius_ >= 0)) throw props.error("radius", "must not be negative");
    if (!(alpha_ > 0 && alpha_ < 1)) throw props.error("alpha", "must be in (0, 1)");
    if (samples_per_round_ < 1 || samples_per_round_ > 1024)
      throw props.error("samples_per_round", "must be between 1 and 1024");
  }

  void prepare(const Scene& scene) override {
    enabled_ = scene.features().caustic_paths;
    const Vec3 diagonal = scene.bounds().hi - scene.bounds().lo;
    initial_radius_ = radius_ > 0 ? radius_ : std::max(length(diagonal) / 200, 1e-6f);
    rounds_ = 0;
  }

  // Without photons there is nothing to refine between passes.
  uint32_t max_pass_samples() const override { return enabled_ ? uint32_t(samples_per_round_) : 16; }

  void begin_pass(const Scene& scene, uint32_t pass, uint64_t seed) override {
    rounds_ = pass + 1;
    if (!enabled_) return;
    map_ = PhotonMap(trace_photons(scene, PhotonPaths::Caustic, uint64_t(photons_), pass, seed, settings_),
                     round_radius(pass));
    gather_.emplace(map_, uint64_t(photons_), settings_.max_depth);
  }

  Color Li(const Scene& scene, Ray ray, Sampler& sampler) const override {
    return trace_path(scene, ray, sampler, settings_, enabled_ ? &*gather_ : nullptr);
  }

  std::string plan(const Scene& scene) const override {
    if (!scene.features().caustic_paths)
      return std::string("photon: caustic photon pass skipped (") + scene.features().caustics_reason +
             "); path tracing alone, at path's cost";
    return std::string("photon: ") + std::to_string(photons_) + " caustic photons per round (" +
           scene.features().caustics_reason + "), path tracing for the rest";
  }

  std::string describe() const override {
    return caustica::describe("photon", settings_) + " photons=" + std::to_string(photons_) +
           " radius=" + std::to_string(radius_) + " alpha=" + std::to_string(alpha_) +
           " samples_per_round=" + std::to_string(samples_per_round_) + " rounds=" + std::to_string(rounds_) +
           (enabled_ ? "" : " (photon pass skipped)");
  }

 private:
  // r_i^2 = r_0^2 prod_{k=1}^{i} (k + alpha) / (k + 1)  (Knaus and Zwicker 2011, eq. 20)
  float round_radius(uint32_t round) const {
    double r2 = double(initial_radius_) * initial_radius_;
    for (uint32_t k = 1; k <= round; ++k) r2 *= (k + alpha_) / (k + 1.0);
    return float(std::sqrt(r2));
  }

  PathSettings settings_;
  int64_t photons_;
  float radius_, alpha_;
  int64_t samples_per_round_;
  bool enabled_ = false;
  float initial_radius_ = 0;
  uint32_t rounds_ = 0;
  PhotonMap map_;
  std::optional<CausticGather> gather_;
};

}  // namespace

CAUSTICA_REGISTER_PLUGIN(
    PhotonIntegrator, "integrator", "photon",
    path_settings_params({{"photons", ParamType::Integer, "100000", "photons traced per round"},
                          {"radius", ParamType::Float, "0", "initial gather radius, 0 to derive it from the scene"},
                          {"alpha", ParamType::Float, "0.7", "radius reduction parameter in (0, 1)"},
                          {"samples_per_round", ParamType::Integer, "1", "samples per pixel per photon round"}}),
    {});

}  // namespace caustica
