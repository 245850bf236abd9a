#include "integrators/bidirectional/strategy_weight.h"

#include <algorithm>

#include "core/registry/properties.h"
#include "integrators/bidirectional/path_density.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

// Densities through a delta lobe are stored as 0 on both sides of a ratio;
// reading them as 1 lets the discrete choices cancel.
float remap(float pdf) { return pdf != 0 ? pdf : 1; }

float h(MisHeuristic heuristic, float r) { return heuristic == MisHeuristic::Power ? r * r : r; }
// In double where a ratio meets a partial sum: each alone may leave
// float's range where their product does not.
double h(MisHeuristic heuristic, double r) { return heuristic == MisHeuristic::Power ? r * r : r; }

// The sum over every strategy used of h(p' / p), where p is the density of
// connection (s, t) and p' that of the other strategy, (s, t) itself
// included where used. `joined`: the path is that connection's, whose end
// camera[t-1] scatters toward light[s-1] whatever lobe its subpath left it
// by; otherwise a merge stands in for it, and camera[t-1] passes the path
// on as its subpath did, through a delta lobe if so.
float ratio_sum(std::span<const PathVertex> light, std::span<const PathVertex> camera, int s, int t,
                MisHeuristic heuristic, const ConnectionDensities& densities, const Merging& merging, bool joined) {
  const int k = s + t - 1;  // the path has vertices x_0 (on the light) .. x_k (the camera)
  const auto [light_end, light_before_end, camera_end, camera_before_end] = densities;

  const PathVertex& origin = s > 0 ? light[0] : camera[k];
  // Ratios of each other strategy's density to this one's, walking away
  // from the connection one vertex at a time. Strategy s' joins x_{s'-1}
  // to x_{s'}, so it is possible unless one of them scatters through a
  // delta lobe (the connection's own endpoints never do) or, for s' = 0, the
  // path starts on a delta light; a one-segment path from the camera to an
  // environment light has no strategy s' = 1. Merging at x_i has ratio
  // p_{i+1} / p times the camera side's density of x_i times eta; it is
  // possible unless the path leaves x_i through a delta lobe, which a merge
  // (evaluating the BSDF between the two subpaths' directions) never gives.
  float sum = joined || (merging.connections && !camera[t - 1].delta) ? 1 : 0, r = 1;
  const bool merges = merging.eta > 0;
  // Whether the path scatters at x_i through a delta lobe: as its subpath
  // left it, except at the connection's ends, where the BSDF is evaluated
  // (at x_s only when joined: a merge's x_s passes the path on as its
  // subpath did).
  const auto delta_at = [&](int i) {
    if (i >= k || i == s - 1 || (i == s && joined)) return false;
    return i >= s ? camera[k - i].delta : light[i].delta;
  };
  const auto merge_allowed = [&](int i) { return !merging.after_delta_only || delta_at(i + 1); };
  // Strategies s' > s: x_i = camera[k - i] for i >= s, whose density from
  // the light side is the connection's for i = s and s + 1; camera[t-3]'s
  // partial sum holds the rest (i >= s + 2).
  for (int i = s; i < std::min(k, s + 2); ++i) {
    const int j = k - i;
    const float from_light = i == s ? camera_end : camera_before_end;
    r *= remap(from_light) / remap(camera[j].pdf_fwd);
    const int sp = i + 1;
    const bool possible = sp == k && k == 1
                              ? !origin.environment && !origin.delta_light
                              : (i == 0 || (i == s && joined) || !camera[j].delta) && (sp == k || !camera[j - 1].delta);
    if (possible && merging.connections) sum += h(heuristic, r);
    if (merges && i >= 1 && ((i == s && joined) || !camera[j].delta) && merge_allowed(i) && mergeable(camera[j]))
      sum += h(heuristic, r * remap(camera[j].pdf_fwd) * merging.eta);
  }
  if (t >= 4 && camera[t - 3].mis_partial > 0) sum += float(h(heuristic, double(r)) * camera[t - 3].mis_partial);
  // Strategies s' < s: x_i = light[i], whose density from the camera side
  // is the connection's for i = s - 1 and s - 2; light[s-3]'s partial sum
  // holds the rest.
  r = 1;
  for (int sp = s - 1; sp >= std::max(0, s - 2); --sp) {
    const float from_camera = sp == s - 1 ? light_end : light_before_end;
    r *= remap(from_camera) / remap(light[sp].pdf_fwd);
    const bool possible =
        sp == 0 ? !origin.delta_light : (sp == 1 || !light[sp - 1].delta) && (sp == s - 1 || !light[sp].delta);
    if (possible && (merging.connections || sp == 0)) sum += h(heuristic, r);
    if (merges && sp >= 1 && (sp == s - 1 || !light[sp].delta) && merge_allowed(sp) && mergeable(light[sp]))
      sum += h(heuristic, r * remap(light[sp].pdf_fwd) * merging.eta);
  }
  if (s >= 3 && light[s - 3].mis_partial > 0) sum += float(h(heuristic, double(r)) * light[s - 3].mis_partial);
  return sum;
}

// What the end of a subpath of n vertices, side[n-1], gives when joined to
// `other`: the density of sampling `other` from it, and that of sampling
// side[n-2] back from it (0 when the end starts its subpath). `other` ends
// the other subpath, so a specular chain it starts (possible where a merge
// stands in for the connection) runs on toward that subpath's start.
DensityPair end_densities(const Scene& scene, std::span<const PathVertex> side, int n, const PathVertex& other) {
  if (n >= 2) return scatter_densities(side[n - 2], side[n - 1], other, other.chain_cos_bwd);
  return {scatter_density(scene, nullptr, side[0], other, other.chain_cos_bwd), 0};
}

// The connection's densities from what its two ends give (end_densities).
ConnectionDensities from_ends(DensityPair camera_side, DensityPair light_side) {
  return {.light_end = camera_side.to_next,
          .light_before_end = light_side.to_prev,
          .camera_end = light_side.to_next,
          .camera_before_end = camera_side.to_prev};
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

ConnectionDensities connection_densities(const Scene& scene, std::span<const PathVertex> light,
                                         std::span<const PathVertex> camera, int s, int t) {
  ConnectionDensities d;
  if (s == 0) {
    d.camera_end = light_origin_density(scene, camera[t - 1]);
    if (t >= 2) d.camera_before_end = emission_density(camera[t - 1], camera[t - 2], camera[t - 2].chain_cos_bwd);
    return d;
  }
  return from_ends(end_densities(scene, camera, t, light[s - 1]), end_densities(scene, light, s, camera[t - 1]));
}

ConnectionDensities joined_densities(const PathVertex& camera_prev, const PathVertex& camera_end,
                                     const ScatteringBothWays& at_camera, const PathVertex& light_prev,
                                     const PathVertex& light_end, const ScatteringBothWays& at_light) {
  return from_ends(area_densities(camera_prev, camera_end, light_end, at_camera.forward, at_camera.backward),
                   area_densities(light_prev, light_end, camera_end, at_light.forward, at_light.backward));
}

ConnectionDensities light_sample_densities(const Scene& scene, const PathVertex& camera_prev,
                                           const PathVertex& camera_end, const ScatteringBothWays& at_camera,
                                           const PathVertex& light) {
  return from_ends(area_densities(camera_prev, camera_end, light, at_camera.forward, at_camera.backward),
                   end_densities(scene, {&light, 1}, 1, camera_end));
}

DensityPair merge_camera_densities(const Scene& scene, std::span<const PathVertex> camera, int t) {
  // A merge's camera[t-1] passes the path on as its subpath did: through a
  // delta lobe, whose densities are read as the subpath stored them (0),
  // not as the other lobes of a BSDF that has both (a plastic's coat).
  if (camera[t - 1].delta) return {0, 0};
  return end_densities(scene, camera, t, camera[t]);
}

ConnectionDensities merge_densities(std::span<const PathVertex> light, int s, const PathVertex& camera_end,
                                    DensityPair camera_side, const ScatteringBothWays& at_merge) {
  return from_ends(camera_side, area_densities(light[s - 2], light[s - 1], camera_end, at_merge.backward,
                                               at_merge.forward, camera_end.chain_cos_bwd));
}

float strategy_weight(const Scene& scene, std::span<const PathVertex> light, std::span<const PathVertex> camera, int s,
                      int t, MisHeuristic heuristic) {
  return strategy_weight(light, camera, s, t, heuristic, connection_densities(scene, light, camera, s, t));
}

float strategy_weight(std::span<const PathVertex> light, std::span<const PathVertex> camera, int s, int t,
                      MisHeuristic heuristic, const ConnectionDensities& densities, const Merging& merging) {
  return 1 / ratio_sum(light, camera, s, t, heuristic, densities, merging, true);
}

float merge_weight(std::span<const PathVertex> light, std::span<const PathVertex> camera, int s, int t,
                   MisHeuristic heuristic, const ConnectionDensities& densities, const Merging& merging) {
  return h(heuristic, remap(densities.light_end) * merging.eta) /
         ratio_sum(light, camera, s, t, heuristic, densities, merging, false);
}

void sum_partial_ratios(std::span<PathVertex> path, MisHeuristic heuristic, const Merging& merging) {
  const bool merges = merging.eta > 0;
  // The vertex after v_n toward the camera: the camera subpath's previous
  // one, the light subpath's next (both within the subpath wherever a
  // partial sum is read).
  const bool from_camera = !path.empty() && path[0].kind == PathVertex::Kind::Camera;
  const auto next_toward_camera_delta = [&](size_t n) { return from_camera ? path[n - 1].delta : path[n + 1].delta; };
  double partial = 0;
  // The last two vertices' reverse densities depend on the connection: no
  // weight reads their sums.
  for (size_t n = 0; n < path.size(); ++n) {
    PathVertex& v = path[n];
    if (n + 2 >= path.size()) {
      v.mis_partial = 0;
      continue;
    }
    double here = 0;
    if (n == 0) {
      here = v.kind == PathVertex::Kind::Light && !v.delta_light ? 1 : 0;
    } else {
      if (merging.connections && !v.delta && (n == 1 || !path[n - 1].delta)) here += 1;
      if (merges && !v.delta && (!merging.after_delta_only || next_toward_camera_delta(n)) && mergeable(v))
        here += h(heuristic, double(remap(v.pdf_fwd)) * merging.eta);
    }
    // With no strategy yet the ratio is not read: the camera's own reverse
    // density (a pinhole's) may not be finite.
    partial = here + partial == 0 ? 0 : h(heuristic, double(remap(v.pdf_rev)) / remap(v.pdf_fwd)) * (here + partial);
    v.mis_partial = partial;
  }
}

bool mergeable(const PathVertex& v) { return v.is_surface() && (v.bsdf->lobes() & ~kDelta); }

MisHeuristic read_mis_heuristic(const Properties& props) {
  const std::string name = props.get_string("mis");
  if (name == "power") return MisHeuristic::Power;
  if (name == "balance") return MisHeuristic::Balance;
  throw props.error("mis", "must be power or balance, not '" + name + "'");
}

}  // namespace caustica
