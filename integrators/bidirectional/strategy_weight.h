#pragma once

#include <span>

#include "integrators/bidirectional/path_density.h"
#include "integrators/bidirectional/path_vertex.h"

namespace caustica {

class Scene;

enum class MisHeuristic { Balance, Power };

// Vertex merging (vcm) as further strategies. Merging at an interior
// vertex x_i (0 < i < k) that scatters off a non-delta surface lobe
// (mergeable()) takes x_0 .. x_i from the light subpath and x_{i+1} .. x_k
// from the camera subpath, whose own next vertex must fall within the merge
// radius r of x_i. Merged against N light subpaths, its density is that of
// connection strategy s = i + 1 times the camera side's density of x_i times
// eta = N pi r^2 (Georgiev et al. 2012, section 4.2), so it enters the same
// ratios. The default, eta = 0, is bdpt: no merging.
struct Merging {
  float eta = 0;
  // Whether the connections (strategies s >= 1) are used; without them
  // (vcm's merge-only mode) the strategies are s = 0 and the merges.
  bool connections = true;
  // Whether merging at x_i is restricted to where the path scatters at
  // x_{i+1}, its next vertex toward the camera, through a delta lobe: the
  // merges that find specular-diffuse-specular paths, which no connection
  // can, and only at the camera vertices reached through glass or a
  // mirror. A strategy left out of every path's weights keeps the estimate
  // unbiased, and most camera vertices then look up no light vertex.
  bool after_delta_only = false;
};

// Sets every vertex's mis_partial for the heuristic and merging the
// subpath's strategies will be weighed with: P_n = h(q_n) (c_n + P_{n-1}),
// q_n = pdf_rev / pdf_fwd (a delta lobe's 0 read as 1) and c_n the
// strategies at v_n that are possible (a connection unless v_n or v_{n-1}
// scatters through a delta lobe, or at a light's origin unless the light
// is delta; a merge where v_n is mergeable and left through a non-delta
// lobe, with its ratio h(pdf_fwd eta)). The camera's own vertex starts no
// strategy. The pdf_fwd and pdf_rev must be set (compute_densities).
void sum_partial_ratios(std::span<PathVertex> path, MisHeuristic heuristic, const Merging& merging);

// Whether a path may merge at `v`: a surface vertex with a non-delta lobe.
bool mergeable(const PathVertex& v);

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

// The densities a connection decides, per unit area: of x_{s-1} and x_{s-2}
// as the camera side would sample them (light_end, light_before_end), and
// of x_s and x_{s+1} as the light side would (camera_end,
// camera_before_end); 0 where a subpath has no such vertex.
struct ConnectionDensities {
  float light_end = 0, light_before_end = 0, camera_end = 0, camera_before_end = 0;
};
ConnectionDensities connection_densities(const Scene& scene, std::span<const PathVertex> light,
                                         std::span<const PathVertex> camera, int s, int t);
// The same for a connection of light[s-1] to camera[t-1] with s, t >= 2,
// from what scattering_both_ways gave at its ends (at the camera end
// toward camera[t-2] and the light end, at the light end toward
// light[s-2] and the camera end): bdpt has them with the BSDF values.
ConnectionDensities joined_densities(const PathVertex& camera_prev, const PathVertex& camera_end,
                                     const ScatteringBothWays& at_camera, const PathVertex& light_prev,
                                     const PathVertex& light_end, const ScatteringBothWays& at_light);
// The same for strategy (1, t) with t >= 2, camera[t-1] joined to the
// point `light` sampled on an emitter, from what scattering_both_ways gave
// at the camera end (toward camera[t-2] and the light point): bdpt has it
// with the BSDF value.
ConnectionDensities light_sample_densities(const Scene& scene, const PathVertex& camera_prev,
                                           const PathVertex& camera_end, const ScatteringBothWays& at_camera,
                                           const PathVertex& light);
// The same for merging at light[s-1] with camera[t], the camera subpath's
// vertex within the radius, which stands in for light[s-1] where the
// connection (s, t) of light[s-1] to camera[t-1] needs that vertex's
// position or scattering (Georgiev et al. 2012). The camera side's part
// depends on camera[t] alone (merge_camera_densities, once per camera
// vertex); the light side's comes from `at_merge`, what
// scattering_both_ways gave at camera[t] toward camera[t-1] and toward
// light[s-2]. So a merge costs one BSDF evaluation, whatever the path's
// length. Where the two vertices coincide these are connection_densities',
// except where camera[t-1] left through a delta lobe: a merge passes the
// path on through it, so its densities there are the delta's, not those a
// connection's BSDF evaluation gives. s >= 2, t >= 1.
DensityPair merge_camera_densities(const Scene& scene, std::span<const PathVertex> camera, int t);
ConnectionDensities merge_densities(std::span<const PathVertex> light, int s, const PathVertex& camera_end,
                                    DensityPair camera_side, const ScatteringBothWays& at_merge);
// The weight from densities the caller already has; with `merging`,
// weighed against the merges too.
float strategy_weight(std::span<const PathVertex> light, std::span<const PathVertex> camera, int s, int t,
                      MisHeuristic heuristic, const ConnectionDensities& densities, const Merging& merging = {});
// The weight of merging at light[s-1], the light subpath's vertex within
// the radius of the camera subpath's next one: the path is that of
// connection (s, t), light[s-1] joined to camera[t-1], whose densities
// `densities` holds.
float merge_weight(std::span<const PathVertex> light, std::span<const PathVertex> camera, int s, int t,
                   MisHeuristic heuristic, const ConnectionDensities& densities, const Merging& merging);

// The heuristic a parameter `mis` names ("power" or "balance").
class Properties;
MisHeuristic read_mis_heuristic(const Properties& props);

}  // namespace caustica
