// guided_path: path tracing (as `path`) whose directions are drawn from a
// distribution learnt from the scene while it renders, "practical path
// guiding" (Müller, Gross, Novák 2017): a binary tree over space whose
// regions each hold a quadtree over directions. Pass 0 (1 sample per pixel)
// samples by the BSDF alone and records, at every vertex it could guide,
// the radiance the rest of its path brought back; each training pass after
// it (2, 4, 8, ... samples per pixel) samples by the distribution the pass
// before recorded, and records for the next. Later passes all sample by
// the last one.
//
// At a guided vertex a direction comes from the BSDF with probability
// bsdf_fraction, from the learned distribution otherwise, and is weighed by
// one-sample MIS (the balance heuristic: f over the mixture's density);
// next-event estimation weighs its light sample against the same mixture.
// Vertices with a delta lobe are not guided. Every pass's estimate is
// unbiased, since the distribution it samples by is fixed before it starts
// and the mixture has density wherever the BSDF has; so every sample of
// every pass weighs the same in the image, whatever order the passes come
// in, and training costs no samples.
//
// What teaches the directions is, by default, light paths traced from the
// emitters in each training pass (light_paths per camera sample of the
// pass): a camera path finds the bright patch behind a narrow opening by
// luck and records it as one huge, lonely value, while many light paths
// reach it with bounded power each. light_paths 0 keeps the paper's
// records of camera paths. Either way roulette judges a guided path by the
// BSDF's weight of its directions, not the mixture's: a direction the
// guide prefers has a high density and a small weight, and a roulette on
// that weight would end guided paths in proportion as they were sent
// toward the light.
//
// Guiding costs time at every vertex, and guided paths stay longer in the
// scene, so it pays only where it cuts the variance further than that:
// from pass 2 on, each training pass's samples are weighed against pass
// 0's, unguided (GuidingPayoff), less the emission their camera rays saw
// directly, and where the guided ones cost more per unit of error, guiding
// stops and every later sample is path's. The decision uses earlier
// samples only, so each later sample stays unbiased.
//
// After the training, roulette is adjoint-driven where a path's region
// has learnt the radiance it sends back (GuidedRadiance::adjoint_survival):
// camera paths of the training passes record it at every vertex they
// could guide.
//
// Where a guide has learnt that its light samples reach no light (none of
// 256 or more in a training pass added anything), its guided vertices
// take none, and the emission their directions find counts in full.
//
// Records are summed in fixed point (FixedPointSum), and the trees are
// rebuilt from them between passes in one thread, so the image is the same
// for any thread count. A render of a range of samples, a replayed sample
// and each MPI rank trace the training passes they do not render
// themselves, for learning alone, and so sample by the same distributions
// as one render of every sample.
//
//   <integrator type="guided_path"><integer name="training_passes" value="6"/></integrator>

#include <algorithm>
#include <cstdio>

#include "core/registry/properties.h"
#include "core/render/pass_schedule.h"
#include "core/render/path_settings.h"
#include "core/render/pixel_integrator.h"
#include "core/render/pixel_loop.h"
#include "core/render/sample_wavelengths.h"
#include "core/scene/scene.h"
#include "integrators/path/guiding/guided_radiance.h"
#include "integrators/path/guiding/guiding_payoff.h"
#include "integrators/path/guiding/guiding_settings.h"
#include "integrators/path/guiding/light_path_records.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class GuidedPathIntegrator;

// One render's guiding trees and where their training stands.
class GuidedEstimator final : public PixelEstimator {
 public:
  GuidedEstimator(const GuidedPathIntegrator& integrator, const Scene& scene, uint64_t seed);

  uint32_t max_pass_samples() const override { return std::max(16u, 1u << (training_passes_ - 1)); }
  bool begin_pass(const PassRange& range, const std::atomic<bool>* stop) override;
  void sample(Vec2i pixel, const Ray& ray, Sampler& sampler, std::span<float> out) const override;
  std::string summary() const override;

 private:
  // Traces pass `pass` over every pixel, recording only.
  bool train_alone(uint32_t pass, const std::atomic<bool>* stop);
  bool record_light_paths_of(uint32_t pass, const std::atomic<bool>* stop);
  // Starts recording pass `pass`: its light paths, and its samples' payoff.
  bool start_recording(uint32_t pass, const std::atomic<bool>* stop);

  const Scene& scene_;
  uint64_t seed_;
  const PathSettings& path_;
  const GuidingSettings& guiding_;
  uint32_t training_passes_;  // 0 where guiding cannot help the scene
  std::unique_ptr<GuidingTree> tree_;
  std::unique_ptr<GuidingPayoff> payoff_;
  GuidedWalk walk_;
  uint32_t built_ = 0;          // the training passes the current distribution learnt from
  int64_t recorded_pass_ = -1;  // the pass whose records the recorders hold, every pixel's
  uint32_t passes_alone_ = 0;
  int64_t capped_after_ = -1;  // the first pass after which the memory cap held refinement back
  int64_t unpaid_after_ = -1;  // the guided pass after which unguided paths were judged cheaper
  GuidingPayoff::Verdict verdict_;
};

class GuidedPathIntegrator final : public PixelIntegrator {
 public:
  explicit GuidedPathIntegrator(const Properties& props)
      : path_(read_path_settings(props)), guiding_(read_guiding_settings(props)) {}

  std::unique_ptr<PixelEstimator> estimator(const Scene& scene, uint64_t seed) const override {
    return std::make_unique<GuidedEstimator>(*this, scene, seed);
  }

  bool renders_media() const override { return true; }
  bool renders_spectral() const override { return true; }
  // Each path keeps its own time; what guides it is learned from all of them.
  bool renders_motion() const override { return true; }

  std::string plan(const Scene& scene) const override {
    const std::string pointless = guiding_pointless(scene, path_.max_depth);
    if (!pointless.empty()) return plugin_name() + ": guiding skipped (" + pointless + "); renders as path";
    const uint32_t spp = (1u << guiding_.training_passes) - 1;
    char light[32];
    std::snprintf(light, sizeof light, "%g", guiding_.light_paths);
    const std::string teacher = guiding_.light_paths > 0 ? std::string("light paths (") + light + " per camera sample)"
                                                         : std::string("the camera paths' own records");
    return plugin_name() + ": path tracing with directions learnt from " + teacher + " over " +
           std::to_string(guiding_.training_passes) + " training passes (" + std::to_string(spp) +
           " samples per pixel, each counted in the image), mixed with BSDF sampling (bsdf_fraction " +
           std::to_string(guiding_.bsdf_fraction) + ") by one-sample MIS; surfaces with delta lobes unguided, and " +
           "where a guide learnt from fewer than " + std::to_string(guiding_.refinement.min_records) + " records" +
           (scene.features().media ? "; media: scattering in a medium follows its phase function, unguided" : "") +
           "; trees capped at " + std::to_string(guiding_.refinement.max_bytes >> 20) + " MiB" +
           (guiding_.adjoint_roulette > 0
                ? "; after the training, roulette by expected contribution (adjoint_roulette " +
                      std::to_string(guiding_.adjoint_roulette) + ")"
                : std::string("; path's roulette")) +
           (guiding_.skip_unseen_lights ? std::string("; no light samples where a guide learnt they reach no light")
                                        : std::string()) +
           (guiding_.always_guide ? std::string("; guides every pass (always_guide)")
                                  : std::string("; guiding stops after a training pass whose guided samples cost more "
                                                "per unit of error than pass 0's unguided ones"));
  }

  std::string distributed_note() const override {
    return "each rank traces the training passes itself, for learning alone, and renders its own share of the "
           "samples by the same distributions";
  }

 private:
  friend class GuidedEstimator;
  PathSettings path_;
  GuidingSettings guiding_;
};

GuidedEstimator::GuidedEstimator(const GuidedPathIntegrator& integrator, const Scene& scene, uint64_t seed)
    : scene_(scene),
      seed_(seed),
      path_(integrator.path_),
      guiding_(integrator.guiding_),
      training_passes_(guiding_pointless(scene, integrator.path_.max_depth).empty()
                           ? uint32_t(integrator.guiding_.training_passes)
                           : 0),
      tree_(std::make_unique<GuidingTree>(scene.bounds())),
      payoff_(std::make_unique<GuidingPayoff>(scene.sensor().film()->width(), scene.sensor().film()->height())) {
  walk_.bsdf_fraction = guiding_.bsdf_fraction;
  walk_.camera_directions = !(guiding_.light_paths > 0);
  walk_.adjoint_roulette = guiding_.adjoint_roulette;
  walk_.skip_unseen_lights = guiding_.skip_unseen_lights;
}

bool GuidedEstimator::begin_pass(const PassRange& range, const std::atomic<bool>* stop) {
  const uint32_t target = std::min(range.pass, training_passes_);
  while (unpaid_after_ < 0 && built_ < target) {
    if (recorded_pass_ != int64_t(built_) && !train_alone(built_, stop)) return false;
    tree_->refine(guiding_.refinement, uint64_t(1) << built_);
    if (tree_->capped() && capped_after_ < 0) capped_after_ = built_;
    if (built_ >= GuidingPayoff::kFirstJudged) {
      verdict_ = payoff_->judge();
      if (!guiding_.always_guide && !verdict_.pays()) unpaid_after_ = built_;
    }
    ++built_;
    recorded_pass_ = -1;
  }
  const Pass pass = pass_containing(range.first, max_pass_samples());
  const bool whole_pass = range.first == pass.first && range.count == pass.count;
  const bool guiding = unpaid_after_ < 0;
  walk_.guide = guiding && built_ > 0;
  walk_.record = guiding && range.pass < training_passes_ && whole_pass;
  walk_.after_training = range.pass >= training_passes_;
  if (walk_.record) return start_recording(range.pass, stop);
  return true;
}

bool GuidedEstimator::start_recording(uint32_t pass, const std::atomic<bool>* stop) {
  recorded_pass_ = pass;
  payoff_->begin_pass(pass);
  return record_light_paths_of(pass, stop);
}

bool GuidedEstimator::train_alone(uint32_t pass, const std::atomic<bool>* stop) {
  walk_.guide = built_ > 0;
  walk_.record = true;
  walk_.after_training = false;
  const Film& film = *scene_.sensor().film();
  const uint64_t first = (uint64_t(1) << pass) - 1, count = uint64_t(1) << pass;
  ++passes_alone_;
  if (!start_recording(pass, stop)) return false;
  return for_each_camera_sample(
      scene_, seed_, make_tiles(film.width(), film.height()), first, count, 3, stop, std::nullopt,
      [&](Vec2i pixel, uint64_t, const CameraSample& cs, SampleScratch& s) {
        sample(pixel, cs.ray, *s.sampler, s.values);
      },
      [](const Tile&) {});
}

bool GuidedEstimator::record_light_paths_of(uint32_t pass, const std::atomic<bool>* stop) {
  if (walk_.camera_directions) return true;
  const Film& film = *scene_.sensor().film();
  const auto count =
      uint64_t(guiding_.light_paths * double(film.width()) * double(film.height()) * double(uint64_t(1) << pass));
  return record_light_paths(scene_, *tree_, count, pass, seed_, path_, stop);
}

void GuidedEstimator::sample(Vec2i pixel, const Ray& ray, Sampler& sampler, std::span<float> out) const {
  SampleWavelengths w(scene_, sampler);
  const GuidedPathSample s = trace_guided_path(scene_, ray, sampler, path_, *tree_, walk_, w.get());
  const Color L = w.to_rgb(s.L);
  // What the camera sees directly, guiding cannot change: left in, a pixel
  // on an emitter's edge whose few guided samples all missed it would read
  // pass 0's hit as unguided variance and keep guiding going.
  if (walk_.record) payoff_->add(pixel, L - w.to_rgb(s.seen), s.cost);
  out[0] = L.r;
  out[1] = L.g;
  out[2] = L.b;
}

std::string GuidedEstimator::summary() const {
  if (training_passes_ == 0) return "guiding skipped";
  char mib[32];
  std::snprintf(mib, sizeof mib, "%.2f", double(tree_->bytes()) / double(1 << 20));
  std::string s = "guiding: " + std::to_string(built_) + " of " + std::to_string(training_passes_) +
                  " training passes learnt, " + std::to_string(tree_->regions()) + " regions, " +
                  std::to_string(tree_->directional_nodes()) + " directional nodes, " + mib + " MiB";
  if (capped_after_ >= 0)
    s += ", max_tree_memory reached after pass " + std::to_string(capped_after_) + ": refinement stopped there";
  char figures[160];
  std::snprintf(figures, sizeof figures,
                "relative variance %.3g at a cost of %.3g vertices per sample, against %.3g at %.3g unguided",
                verdict_.guided_variance, verdict_.guided_cost, verdict_.unguided_variance, verdict_.unguided_cost);
  if (unpaid_after_ >= 0)
    s += ", guiding stopped after pass " + std::to_string(unpaid_after_) + " (" + figures +
         "); later samples are unguided";
  else if (built_ > GuidingPayoff::kFirstJudged)
    s += ", pass " + std::to_string(built_ - 1) + ": " + figures;
  if (passes_alone_ > 0) s += ", " + std::to_string(passes_alone_) + " passes traced for learning alone";
  const size_t unlit = tree_->guides_without_lights();
  if (guiding_.skip_unseen_lights && unlit > 0 && unpaid_after_ < 0)
    s += ", no light samples at the guided vertices of " + std::to_string(unlit) +
         " guides whose light samples reached no light";
  return s;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(GuidedPathIntegrator, "integrator", "guided_path", path_settings_params(guiding_params()), {});

}  // namespace caustica
