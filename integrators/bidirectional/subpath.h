#pragma once

#include <vector>

#include "core/geometry/ray.h"
#include "core/render/path_settings.h"
#include "core/sampling/sampler.h"
#include "integrators/bidirectional/path_vertex.h"
#include "integrators/bidirectional/strategy_weight.h"

namespace caustica {

class Scene;

// Replaces `path` with the camera subpath that starts with `ray`: the
// camera vertex, then the surfaces the walk hits, and an environment vertex
// if it escapes into a scene that has one.
// Its length follows settings.max_depth (max_depth + 1 vertices, the
// camera's included), like every walk's roulette (core/transport).
// With `wavelengths` (spectral mode, here and below) the vertices' BSDFs
// and weights are at them.
void trace_camera_subpath(const Scene& scene, const Ray& ray, Sampler& sampler, const PathSettings& settings,
                          std::vector<PathVertex>& path, Wavelengths* wavelengths = nullptr);

// Replaces `path` with a light subpath: an emitter chosen by power, a ray
// it emits, and the surfaces that ray's walk hits (BSDFs in importance
// mode). Empty when the scene has no light to start from. It has at most
// max_depth vertices, the light's included: its last still joins the camera.
// The path is at `time` (see Ray::time); a camera subpath is at its ray's.
void trace_light_subpath(const Scene& scene, Sampler& sampler, float time, const PathSettings& settings,
                         std::vector<PathVertex>& path, Wavelengths* wavelengths = nullptr);

// Sets pdf_fwd and pdf_rev of every vertex from the geometry, the way the
// walks sampled them: a vertex after a delta lobe gets 0 in that direction.
// pdf_rev of the last two vertices depends on the connection made later and
// is left 0. Then the partial sums of the weights its strategies will have
// with `heuristic` and `merging` (sum_partial_ratios).
void compute_densities(const Scene& scene, std::vector<PathVertex>& path, MisHeuristic heuristic,
                       const Merging& merging = {});

}  // namespace caustica
