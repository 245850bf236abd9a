// Photon lookup cost: fixed-radius gathers from a caustic photon map as the
// photon integrator builds it on the glass Cornell box (one round of
// photons traced on one thread, the map's default radius and smaller ones),
// queried at the photons' own positions, where gathers happen in practice.
// Reports queries per second and the photons each query visits.

#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include "core/loader/scene_loader.h"
#include "integrators/photon/photon_tracing.h"

namespace caustica {
namespace {

const std::vector<Photon>& caustic_photons() {
  static const std::vector<Photon> photons = [] {
    const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    const auto scene = load_scene(std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box-glass.xml", {{"res", "8"}});
    TracedPhotons traced;
    trace_photons(*scene, PhotonPaths::Caustic, 1000000, 0, 1, 0, PathSettings{}, traced);
    return traced.all;
  }();
  return photons;
}

// state.range(0): the radius in tenths of a millimetre.
void RadiusGather(benchmark::State& state) {
  const auto& photons = caustic_photons();
  const PhotonMap map(photons, float(state.range(0)) * 1e-4f);
  size_t i = 0, found = 0;
  for (auto _ : state) {
    map.for_each_within(photons[i].p, [&](const Photon&) { ++found; });
    i = (i + 7919) % photons.size();
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["photons_in_map"] = double(photons.size());
  state.counters["photons_per_query"] = double(found) / double(state.iterations());
}
// 4.8 mm is the default radius for this scene (1/200 of its diagonal).
BENCHMARK(RadiusGather)->Arg(12)->Arg(24)->Arg(48);

void BuildMap(benchmark::State& state) {
  const auto& photons = caustic_photons();
  for (auto _ : state) benchmark::DoNotOptimize(PhotonMap(photons, 4.8e-3f).size());
  state.SetItemsProcessed(state.iterations() * int64_t(photons.size()));
}
BENCHMARK(BuildMap);

}  // namespace
}  // namespace caustica

BENCHMARK_MAIN();
