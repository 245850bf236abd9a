#pragma once

#include <atomic>
#include <cstdint>

#include "core/render/path_settings.h"
#include "integrators/path/guiding/spatial_tree.h"

namespace caustica {

class Scene;

// Traces `count` paths from the emitters (chosen by power, as photons are)
// and records in `tree`, wherever one arrives at a guidable surface after
// at least one bounce, the power it brings along the direction it came
// from. Light paths teach the guide what camera paths find only rarely:
// the bright patch a narrow opening shows, which a camera path reaches by
// luck and then records as one huge, lonely value, many light paths reach
// with bounded power each. Their records are a density over directions of
// the light arriving, weighted by its cosine on the surface, which for a
// diffuse surface is the ideal density to sample. Path i of pass `pass`
// draws from (seed, pass, i) and records sum in fixed point, so the trees
// are the same for any thread count. False once `stop` (may be null) turns
// true.
bool record_light_paths(const Scene& scene, GuidingTree& tree, uint64_t count, uint64_t pass, uint64_t seed,
                        const PathSettings& settings, const std::atomic<bool>* stop);

}  // namespace caustica
