#include "integrators/photon/photon_tracing.h"

#include <tbb/parallel_for.h>

#include <algorithm>

#include "core/lights/spectral_emission.h"
#include "core/render/sample_wavelengths.h"
#include "core/scene/scene.h"
#include "core/transport/light_path_start.h"
#include "core/transport/random_walk.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

constexpr uint64_t kBlock = 1024;

// Keeps the photons of the kind asked for where a light walk lands.
class PhotonRecorder {
 public:
  PhotonRecorder(PhotonPaths kind, std::vector<Photon>& out, const Wavelengths* wavelengths)
      : kind_(kind), out_(out), wavelengths_(wavelengths) {}

  WalkAction at_vertex(const WalkVertex& v) {
    if (v.segments >= 2 && (v.bsdf.lobes() & ~kDelta))
      out_.push_back(
          {v.si.p, v.wo, v.si.ng, v.beta, uint32_t(v.segments), wavelengths_ && secondaries_terminated(*wavelengths_)});
    return WalkAction::Continue;
  }
  void escaped(const WalkEscape&) {}
  // Past a non-delta bounce a path is no caustic any more.
  WalkAction scattered(const BsdfSample& bs) {
    return kind_ == PhotonPaths::Caustic && !bs.is_delta() ? WalkAction::Stop : WalkAction::Continue;
  }
  // Photons are kept on surfaces only; one that scatters in a medium goes
  // on (past it, it is no caustic either).
  WalkAction at_medium_vertex(const MediumVertex&) {
    return kind_ == PhotonPaths::Caustic ? WalkAction::Stop : WalkAction::Continue;
  }
  WalkAction scattered_in_medium(const PhaseSample&) { return WalkAction::Continue; }

 private:
  PhotonPaths kind_;
  std::vector<Photon>& out_;
  const Wavelengths* wavelengths_;
};

void trace_photon(const Scene& scene, PhotonPaths kind, Sampler& sampler, float time, const PathSettings& settings,
                  std::vector<Photon>& out, const Wavelengths* round_wavelengths) {
  const auto start = start_light_path(scene, sampler, time);
  if (!start) return;
  SampleWavelengths w(round_wavelengths);
  Wavelengths* wavelengths = w.get();
  PhotonRecorder recorder(kind, out, wavelengths);
  // A photon needs at least one more segment, to the camera: light walks stop one short of max_depth.
  random_walk(scene, start->le.ray, emission_for(*start->emitter, start->beta, wavelengths), TransportMode::Importance,
              light_walk_limits(settings), sampler, recorder, start->emitter->medium(), wavelengths);
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

bool trace_photons(const Scene& scene, PhotonPaths kind, uint64_t count, uint64_t round, uint64_t seed, float time,
                   const PathSettings& settings, TracedPhotons& out, const std::atomic<bool>* stop,
                   const Wavelengths* wavelengths) {
  const auto stopped = [&] { return stop && stop->load(); };
  const size_t blocks = size_t((count + kBlock - 1) / kBlock);
  std::vector<std::vector<Photon>>& found = out.blocks;
  found.resize(blocks);
  for (auto& f : found) f.clear();
  tbb::parallel_for(size_t(0), blocks, [&](size_t b) {
    if (stopped()) return;
    auto sampler = scene.sensor().sampler()->clone();
    for (uint64_t i = b * kBlock; i < std::min(count, (b + 1) * kBlock); ++i) {
      sampler->start_sample(SampleKey::photon_round(round), i, seed);
      trace_photon(scene, kind, *sampler, time, settings, found[b], wavelengths);
    }
  });
  if (stopped()) return false;
  out.all.clear();
  for (const auto& f : found) out.all.insert(out.all.end(), f.begin(), f.end());
  return true;
}

}  // namespace caustica
