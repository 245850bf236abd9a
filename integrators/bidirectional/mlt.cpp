// mlt: Metropolis light transport in primary sample space over bdpt's
// strategies, multiplexed (Hachisuka, Kaplanyan and Dachsbacher 2014). A
// state of a chain is the random numbers of one bdpt strategy for paths of
// one length: they place the camera ray anywhere on the film, draw the
// camera and light subpaths, and choose which strategy (s, t) joins them;
// its value is that strategy's MIS-weighted contribution times the number
// of strategies, and the chain visits states in proportion to its
// luminance. Mutations are large steps (every number afresh, with
// probability `large_step`) and small steps (each number moved by a normal
// offset of deviation `sigma`, wrapped), accepted by Metropolis-Hastings;
// both the state and the proposal are splatted, weighed by the acceptance
// probability (expected values, Veach 1997).
//
// A bootstrap phase of `bootstrap` independent states per path length
// estimates the normalisation b (the image's integral of luminance) and
// starts `chains` chains from states drawn in proportion to their
// luminance. Every pass (iteration) runs width x height mutations spread
// evenly over the chains, so the image after any number of passes is an
// estimate (b times the splats per mutation per pixel); more passes refine
// it. Chain i draws from (seed, i) and the splats sum exactly, so the image
// is the same for any thread count and whichever thread ran which chain.
//
// What other renderers' MLT is known for, and what this one does: results
// that change with the seed more than their error suggests (the image's
// variance is not estimated: the film reports it unknown, and a convergence
// study must use independent seeds); wrong colours with media (mlt refuses
// media and spectral transport, naming the integrators that render them);
// no progressive image (every pass is one); chains stuck on a path they
// cannot leave by small steps (a large step has probability `large_step`,
// and the many chains start from independent bootstrap states).
//
//   <integrator type="mlt"><integer name="max_depth" value="5"/></integrator>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdio>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "core/film/film_buffer.h"
#include "core/film/splat_list.h"
#include "core/registry/properties.h"
#include "core/render/camera_sample.h"
#include "core/render/iterative_integrator.h"
#include "core/render/path_settings.h"
#include "core/sampling/discrete_distribution.h"
#include "core/scene/scene.h"
#include "integrators/bidirectional/camera_connection.h"
#include "integrators/bidirectional/connection.h"
#include "integrators/bidirectional/primary_sample_space.h"
#include "integrators/bidirectional/subpath.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

struct MltSettings {
  int max_depth = 5;
  MisHeuristic heuristic = MisHeuristic::Power;
  float large_step = 0.3f, sigma = 0.01f;
  int64_t bootstrap = 100000, chains = 1000;
};

MltSettings read_mlt_settings(const Properties& props) {
  MltSettings s;
  const int64_t depth = props.get_int("max_depth");
  if (depth < 1 || depth > 64) throw props.error("max_depth", "must be between 1 and 64 (mlt needs a finite depth)");
  s.max_depth = int(depth);
  s.heuristic = read_mis_heuristic(props);
  s.large_step = props.get_float("large_step");
  if (!(s.large_step > 0 && s.large_step <= 1)) throw props.error("large_step", "must be in (0, 1]");
  s.sigma = props.get_float("sigma");
  if (!(s.sigma > 0 && s.sigma < 1)) throw props.error("sigma", "must be in (0, 1)");
  s.bootstrap = props.get_int("bootstrap");
  if (s.bootstrap < 1) throw props.error("bootstrap", "must be at least 1");
  s.chains = props.get_int("chains");
  if (s.chains < 1) throw props.error("chains", "must be at least 1");
  return s;
}

// What a state of the chain contributes: where on the film, and how much.
struct Contribution {
  Vec2 raster;
  Color value;
  float luminance() const { return value.luminance(); }
};

// The numbers' streams.
constexpr int kCameraStream = 0, kLightStream = 1, kConnectionStream = 2;

// The contribution of the state `numbers` holds among the paths of `depth`
// segments: the strategy it chooses, weighed against the others, times
// their number. Subpaths are exactly as long as the strategy needs and
// meet no roulette: a chain keeps to its length.
Contribution evaluate(const Scene& scene, const MltSettings& mlt, PrimarySampleSpace& numbers, int depth) {
  thread_local std::vector<PathVertex> camera, light;
  const Film& film = *scene.sensor().film();
  numbers.start_stream(kCameraStream);
  const Vec2 u_raster = numbers.next_2d();
  const Vec2 raster{u_raster.x * float(film.width()), u_raster.y * float(film.height())};
  const int strategies = depth + 1;
  const int s = std::min(int(numbers.next_1d() * float(strategies)), depth), t = depth + 1 - s;
  PathSettings settings;
  settings.rr_depth = std::numeric_limits<int64_t>::max();
  settings.max_depth = t - 1;
  const Vec2 u_lens = numbers.next_2d();
  const float time = sample_shutter_time(scene, numbers);
  camera.clear();
  // Strategy t = 1 samples its own lens point when it joins the camera.
  if (t >= 2) {
    trace_camera_subpath(scene, scene.sensor().generate_ray(raster, u_lens, time), numbers, settings, camera);
    if (int(camera.size()) < t) return {raster, {}};
  }
  numbers.start_stream(kLightStream);
  light.clear();
  if (s > 0) {
    settings.max_depth = s;
    trace_light_subpath(scene, numbers, time, settings, light);
    if (int(light.size()) < s) return {raster, {}};
  }
  compute_densities(scene, camera, mlt.heuristic);
  compute_densities(scene, light, mlt.heuristic);
  numbers.start_stream(kConnectionStream);
  if (t == 1) {
    const auto c = connect_to_camera(scene, light, s, numbers);
    if (!c) return {raster, {}};
    const float w = strategy_weight(scene, std::span(light).first(size_t(s)), {&c->camera, 1}, s, 1, mlt.heuristic);
    return {c->raster, c->value * (w * float(strategies))};
  }
  const Color value = connect(scene, light, s, camera, t, numbers, nullptr, mlt.heuristic);
  return {raster, value * float(strategies)};
}

// One chain: its numbers, its path length and its current state.
struct Chain {
  PrimarySampleSpace numbers;
  int depth = 1;
  Contribution state;
};

class MltChains final : public IterationState {
 public:
  MltChains(const MltSettings& mlt, const Scene& scene, uint64_t seed);
  bool iterate(uint64_t iteration, const std::atomic<bool>* stop) override;
  Color estimate(Vec2i pixel) const override;
  std::string summary() const override;

 private:
  void run_bootstrap();
  void mutate(Chain& chain, SplatList& splats) const;

  const MltSettings& mlt_;
  const Scene& scene_;
  uint64_t seed_;
  int width_, height_;
  float normalisation_ = 0;  // b: the image's integral of luminance
  std::vector<Chain> chains_;
  std::vector<SplatList> splats_;
  FilmBuffer image_;
  uint64_t iterations_ = 0;
};

class MetropolisLightTransport final : public IterativeIntegrator {
 public:
  explicit MetropolisLightTransport(const Properties& props) : mlt_(read_mlt_settings(props)) {}

  std::unique_ptr<IterationState> begin(const Scene& scene, uint64_t seed) const override {
    return std::make_unique<MltChains>(mlt_, scene, seed);
  }

  bool renders_motion() const override { return true; }

  std::string plan(const Scene&) const override {
    return "mlt: " + std::to_string(mlt_.chains) + " Markov chains over bdpt's strategies for paths of 1 to " +
           std::to_string(mlt_.max_depth) + " segments, started from " + std::to_string(mlt_.bootstrap) +
           " bootstrap states per length; width x height mutations a pass";
  }

 private:
  MltSettings mlt_;
};

// Bootstrap states are chains of their own index past the chains'.
uint64_t bootstrap_chain(const MltSettings& mlt, uint64_t i) { return uint64_t(mlt.chains) + i; }

MltChains::MltChains(const MltSettings& mlt, const Scene& scene, uint64_t seed)
    : mlt_(mlt),
      scene_(scene),
      seed_(seed),
      width_(scene.sensor().film()->width()),
      height_(scene.sensor().film()->height()),
      image_(width_, height_, {"R", "G", "B"}, FilmBuffer::Moments::None) {
  image_.enable_splats();
}

// Independent states of every length; b is the sum over the lengths of
// their mean luminance, and each chain starts from a state drawn in
// proportion to its luminance, its numbers reproduced from its index.
void MltChains::run_bootstrap() {
  const int depths = mlt_.max_depth;
  const size_t n = size_t(mlt_.bootstrap) * size_t(depths);
  std::vector<float> weights(n);
  const auto state = [&](size_t i) {
    Chain c{PrimarySampleSpace(seed_, bootstrap_chain(mlt_, i), mlt_.sigma), int(i % size_t(depths)) + 1, {}};
    c.numbers.mutate(true);
    c.state = evaluate(scene_, mlt_, c.numbers, c.depth);
    c.numbers.accept();
    return c;
  };
  tbb::parallel_for(size_t(0), n, [&](size_t i) {
    const float y = state(i).state.luminance();
    weights[i] = std::isfinite(y) && y > 0 ? y : 0;
  });
  double sum = 0;
  for (float w : weights) sum += w;
  normalisation_ = float(sum / double(mlt_.bootstrap));
  if (!(sum > 0)) return;
  const DiscreteDistribution pick(weights);
  chains_.reserve(size_t(mlt_.chains));
  for (int64_t c = 0; c < mlt_.chains; ++c) {
    PrimarySampleSpace choice(seed_, uint64_t(c), mlt_.sigma);
    chains_.push_back(state(size_t(pick.sample(choice.uniform()))));
    chains_.back().numbers.reseed(seed_, uint64_t(c));
  }
  splats_.resize(chains_.size());
}

bool MltChains::iterate(uint64_t iteration, const std::atomic<bool>* stop) {
  if (iteration == 0) run_bootstrap();
  if (stop && stop->load()) return false;
  const size_t mutations = size_t(width_) * size_t(height_), n = chains_.size();
  tbb::parallel_for(size_t(0), n, [&](size_t c) {
    SplatList& splats = splats_[c];
    splats.clear();
    splats.set_source({{0, 0}, iteration});
    for (size_t m = 0; m < mutations / n + (c < mutations % n ? 1 : 0); ++m) mutate(chains_[c], splats);
  });
  for (const SplatList& list : splats_) {
    image_.add_splats(list, scene_.sensor().film()->filter(), 0, height_);
    image_.record_dropped(list);
  }
  image_.add_splat_paths(1);
  ++iterations_;
  return true;
}

// One Metropolis-Hastings step, splatting the state and the proposal by
// their expected shares.
void MltChains::mutate(Chain& chain, SplatList& splats) const {
  chain.numbers.mutate(chain.numbers.uniform() < mlt_.large_step);
  const Contribution proposal = evaluate(scene_, mlt_, chain.numbers, chain.depth);
  const float y = chain.state.luminance(), y_new = proposal.luminance();
  const float accept = y > 0 ? std::min(1.0f, y_new / y) : 1.0f;
  if (y > 0 && accept < 1) splats.add(chain.state.raster, chain.state.value * ((1 - accept) / y));
  if (y_new > 0 && accept > 0) splats.add(proposal.raster, proposal.value * (accept / y_new));
  if (chain.numbers.uniform() < accept) {
    chain.state = proposal;
    chain.numbers.accept();
  } else {
    chain.numbers.reject();
  }
}

Color MltChains::estimate(Vec2i pixel) const {
  float v[3];
  image_.resolve_pixel(size_t(pixel.y) * width_ + pixel.x, v);
  return Color(v[0], v[1], v[2]) * normalisation_;
}

std::string MltChains::summary() const {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", normalisation_);
  return "passes=" + std::to_string(iterations_) + ", chains=" + std::to_string(chains_.size()) +
         ", normalisation=" + b;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(
    MetropolisLightTransport, "integrator", "mlt",
    {{"max_depth", ParamType::Integer, "5", "longest path, in segments (1 to 64): each chain keeps to one length"},
     {"mis", ParamType::String, "power", "MIS heuristic between the strategies: power (exponent 2) or balance"},
     {"large_step", ParamType::Float, "0.3", "probability that a mutation draws every number afresh, in (0, 1]"},
     {"sigma", ParamType::Float, "0.01", "standard deviation of a small step's offset to each number, in (0, 1)"},
     {"bootstrap", ParamType::Integer, "100000", "independent states per path length that estimate the normalisation"},
     {"chains", ParamType::Integer, "1000", "Markov chains, started from bootstrap states"}},
    {});

}  // namespace caustica
