#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/geometry/ray.h"
#include "integrators/bidirectional/path_vertex.h"
#include "core/sampling/sampler.h"

namespace caustica {

class Scene;

// How long a subpath may grow. Russian roulette works as in `path`: from
// the rr_depth-th vertex after the subpath's origin on, a subpath survives
// with probability min(max_component(throughput) * eta_scale,
// rr_max_survival), throughput counting scattering only (not emission), so
// light and camera subpaths are judged alike.
struct SubpathLimits {
  size_t max_vertices = SIZE_MAX;  // the origin included
  int64_t rr_depth = 5;
  float rr_max_survival = 0.95f;
};

// Vertices in path length: for max_depth segments (-1 unlimited) a camera
// subpath needs max_depth + 1 vertices, a light subpath max_depth (its last
// vertex still connects to the camera).
SubpathLimits camera_subpath_limits(int64_t max_depth, int64_t rr_depth, float rr_max_survival);
SubpathLimits light_subpath_limits(int64_t max_depth, int64_t rr_depth, float rr_max_survival);

// Replaces `path` with the camera subpath that starts with `ray`: the
// camera vertex, then the surfaces the walk hits, and an environment vertex
// if it escapes into a scene that has one.
void trace_camera_subpath(const Scene& scene, const Ray& ray, Sampler& sampler, const SubpathLimits& limits,
                          std::vector<PathVertex>& path);

// Replaces `path` with a light subpath: an emitter chosen by power, a ray
// it emits, and the surfaces that ray's walk hits (BSDFs in importance
// mode). Empty when the scene has no light to start from.
void trace_light_subpath(const Scene& scene, Sampler& sampler, const SubpathLimits& limits,
                         std::vector<PathVertex>& path);

// Sets pdf_fwd and pdf_rev of every vertex from the geometry, the way the
// walks sampled them: a vertex after a delta lobe gets 0 in that direction.
// pdf_rev of the last two vertices depends on the connection made later and
// is left 0.
void compute_densities(const Scene& scene, std::vector<PathVertex>& path);

}  // namespace caustica
