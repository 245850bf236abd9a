#pragma once

#include <span>

#include "integrators/bidirectional/path_vertex.h"

namespace caustica {

class Scene;

enum class MisHeuristic { Balance, Power };

// The multiple importance sampling weight of bidirectional strategy (s, t):
// the path made of light[0..s) followed by camera[t-1..0], sampled with s
// light and t camera vertices, weighed against every other (s', t') with
// s' + t' = s + t and t' >= 1 that could have sampled it (Veach 1997,
// section 10.2). Strategies that would have to connect through a delta lobe,
// or hit a light at a delta position, cannot and are left out.
//
// Each subpath's vertices carry their densities (compute_densities); the
// densities that depend on the connection itself are evaluated here. For
// s = 1 and t = 1 the spans hold the endpoint the connection sampled (a new
// light or lens point) instead of the subpath's own. For s = 0, camera[t-1]
// is the emitting vertex, its emitter set.
float strategy_weight(const Scene& scene, std::span<const PathVertex> light, std::span<const PathVertex> camera, int s,
                      int t, MisHeuristic heuristic);

}  // namespace caustica
