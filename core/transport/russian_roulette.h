#pragma once

#include <algorithm>
#include <cstdint>

#include "core/math/color.h"
#include "core/sampling/sampler.h"

namespace caustica {

// The one Russian-roulette policy of every walk (camera paths, light paths,
// photons). After scattering at a vertex `segments` segments from the
// walk's origin, with segments >= rr_depth, the walk survives with
// probability
//   q = min(max_component(throughput) * eta_scale, rr_max_survival)
// and a survivor's weights are divided by q, which keeps every estimator
// unbiased. `throughput` is the product of the scattering weights
// f |cos| / pdf alone (what the emitter or the camera put in does not
// count, so light and camera paths are judged alike); `eta_scale` is the
// product of eta^2 over refractions in radiance mode, undoing the 1/eta^2
// by which refraction scales radiance, so a path is not killed merely for
// having entered glass (importance carries no such factor: it stays 1).
struct RussianRoulette {
  int64_t rr_depth = 5;
  float rr_max_survival = 0.95f;

  // Draws one number where roulette applies, none before rr_depth.
  bool survives(int64_t segments, const Color& throughput, float eta_scale, Sampler& sampler, float* q) const {
    *q = 1;
    if (segments < rr_depth) return true;
    *q = std::min(throughput.max_component() * eta_scale, rr_max_survival);
    return sampler.next_1d() < *q;
  }
};

}  // namespace caustica
