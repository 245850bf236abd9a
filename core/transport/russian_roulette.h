#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/math/color.h"
#include "core/sampling/sampler.h"

namespace caustica {

// The one Russian-roulette policy of every walk (camera paths, light paths,
// photons). After scattering at a vertex `segments` segments from the
// walk's origin, with segments >= rr_depth, a walk whose
//   t = max_component(throughput) * eta_scale
// has fallen below rr_threshold survives with probability
//   q = min(t, rr_max_survival)
// and a survivor's weights are divided by q, which keeps every estimator
// unbiased; a walk at or above the threshold always goes on. Rouletting
// walks that still carry much of what they started with (Mitsuba's rule,
// an infinite threshold) multiplies the rare large contributions they go
// on to find: on the glass box, camera paths that reach the light through
// the sphere. `throughput` is the product of the scattering weights
// f |cos| / pdf alone (what the emitter or the camera put in does not
// count, so light and camera paths are judged alike); `eta_scale` is the
// product of eta^2 over refractions in radiance mode, undoing the 1/eta^2
// by which refraction scales radiance, so a path is not killed merely for
// having entered glass (importance carries no such factor: it stays 1).
struct RussianRoulette {
  int64_t rr_depth = 5;
  float rr_max_survival = 0.95f;
  float rr_threshold = 0.1f;

  // Draws one number from rr_depth on, none before, whether or not the walk
  // is below the threshold: each dimension of a sample keeps its meaning. A
  // throughput that is not finite always meets roulette (NaN ends the walk),
  // so that a broken path cannot go on for ever in a closed scene.
  bool survives(int64_t segments, const Color& throughput, float eta_scale, Sampler& sampler, float* q) const {
    *q = 1;
    if (segments < rr_depth) return true;
    const float u = sampler.next_1d();
    const float t = throughput.max_component() * eta_scale;
    if (t >= rr_threshold && std::isfinite(t)) return true;
    *q = std::min(t, rr_max_survival);
    return u < *q;
  }
};

}  // namespace caustica
