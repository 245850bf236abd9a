#include "integrators/path/guiding/light_path_records.h"

#include <tbb/parallel_for.h>

#include <algorithm>

#include "core/lights/spectral_emission.h"
#include "core/render/pass_time.h"
#include "core/scene/scene.h"
#include "core/transport/light_path_start.h"
#include "core/transport/random_walk.h"
#include "core/transport/walk_limits.h"
#include "integrators/path/guiding/guided_radiance.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

constexpr uint64_t kBlock = 1024;

class LightPathRecorder {
 public:
  explicit LightPathRecorder(GuidingTree& tree) : tree_(tree) {}

  WalkAction at_vertex(const WalkVertex& v) {
    if (v.segments >= 2 && guidable(v.bsdf.lobes())) {
      const float power = (v.beta.r + v.beta.g + v.beta.b) / 3;
      if (power > 0) {
        const Vec3 n = dot(v.si.ng, v.wo) < 0 ? -v.si.ng : v.si.ng;
        tree_.region_at(v.si.p).record(normal_bucket(n), direction_to_square(v.wo), power);
      }
    }
    return WalkAction::Continue;
  }
  void escaped(const WalkEscape&) {}
  WalkAction scattered(const BsdfSample&) { return WalkAction::Continue; }
  WalkAction at_medium_vertex(const MediumVertex&) { return WalkAction::Continue; }
  WalkAction scattered_in_medium(const PhaseSample&) { return WalkAction::Continue; }

 private:
  GuidingTree& tree_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

bool record_light_paths(const Scene& scene, GuidingTree& tree, uint64_t count, uint64_t pass, uint64_t seed,
                        const PathSettings& settings, const std::atomic<bool>* stop) {
  const auto stopped = [&] { return stop && stop->load(); };
  const float time = scene.features().motion ? pass_time(pass, seed) : 0.0f;
  tbb::parallel_for(uint64_t(0), (count + kBlock - 1) / kBlock, [&](uint64_t b) {
    if (stopped()) return;
    auto sampler = scene.sensor().sampler()->clone();
    LightPathRecorder recorder(tree);
    for (uint64_t i = b * kBlock; i < std::min(count, (b + 1) * kBlock); ++i) {
      sampler->start_sample(SampleKey::photon_round(pass), i, seed);
      const auto start = start_light_path(scene, *sampler, time);
      if (!start) continue;
      random_walk(scene, start->le.ray, emission_for(*start->emitter, start->beta, nullptr), TransportMode::Importance,
                  light_walk_limits(settings), *sampler, recorder, start->emitter->medium(), nullptr);
    }
  });
  return !stopped();
}

}  // namespace caustica
