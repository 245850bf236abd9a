#pragma once

#include <atomic>
#include <cstdint>
#include <vector>

#include "core/render/path_settings.h"
#include "core/spectral/wavelengths.h"
#include "integrators/photon/photon_map.h"

namespace caustica {

class Scene;

// Which photons a photon pass keeps.
enum class PhotonPaths {
  // Caustics, L S+ D: kept where they land on a surface with a non-delta
  // lobe after one or more delta bounces and nothing else (they may cross
  // media without scattering); the photon stops at its first non-delta
  // bounce or scattering event in a medium.
  Caustic,
  // All indirect light, L (S|D)+ D: kept at every surface with a non-delta
  // lobe after the first bounce (direct light is left to shadow rays);
  // photons scatter in media but are kept on surfaces only.
  Indirect,
};

// The photons of one round: blocks traced in parallel, then joined in
// order. Kept from round to round, so that their memory is reused rather
// than freed and faulted in again.
struct TracedPhotons {
  std::vector<std::vector<Photon>> blocks;
  std::vector<Photon> all;
};

// Traces `count` photons from the emitters (chosen by power) and keeps the
// kind asked for. Photon i of round `round` draws its random numbers from
// (seed, round, i) and blocks of photons are joined in order, so the result
// is the same for any thread count. Photons whose paths could not reach the
// camera within settings.max_depth are not kept. The photons land in
// out.all; false, once `stop` (may be null) turns true: a production-size
// round takes long. With `wavelengths` (spectral mode) every photon carries
// its power at them, the round's wavelengths. Every photon is traced at
// `time` (see Ray::time), the round's.
bool trace_photons(const Scene& scene, PhotonPaths kind, uint64_t count, uint64_t round, uint64_t seed, float time,
                   const PathSettings& settings, TracedPhotons& out, const std::atomic<bool>* stop = nullptr,
                   const Wavelengths* wavelengths = nullptr);

}  // namespace caustica
