#pragma once

#include <span>
#include <vector>

#include "core/sampling/sampler.h"
#include "core/spectral/wavelengths.h"
#include "integrators/bidirectional/strategy_weight.h"

namespace caustica {

class Scene;

// The weighted contribution of strategy (s, t) for t >= 2, as bdpt and vcm
// make it: s = 0 the camera subpath's own emitter (camera[t-1].emitter is
// set by it), s = 1 a point sampled on an emitter and joined to
// camera[t-1] (drawing its sample from `sampler`), s >= 2 light[s-1]
// joined to camera[t-1] through a shadow ray. Weighed against every
// strategy, and against the merges where `merging` has them.
Color connect(const Scene& scene, std::span<const PathVertex> light, int s, std::vector<PathVertex>& camera, int t,
              Sampler& sampler, const Wavelengths* wavelengths, MisHeuristic heuristic, const Merging& merging = {});

}  // namespace caustica
