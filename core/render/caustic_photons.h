#pragma once

#include <cstdint>
#include <vector>

#include "core/render/path_settings.h"
#include "core/render/photon_map.h"

namespace caustica {

class Scene;

// Traces `count` photons from the emitters (chosen by power) and keeps
// those that land on a surface with a non-delta lobe after one or more
// delta bounces and nothing else: the caustic paths L S+ D. A photon is
// kept at every such surface until it scatters off a non-delta lobe.
// Photon i of round `round` draws its random numbers from (seed, round, i)
// and blocks of photons are joined in order, so the result is the same for
// any thread count. Photons whose paths could not reach the camera within
// settings.max_depth are not kept.
std::vector<Photon> trace_caustic_photons(const Scene& scene, uint64_t count, uint32_t round, uint64_t seed,
                                          const PathSettings& settings);

}  // namespace caustica
