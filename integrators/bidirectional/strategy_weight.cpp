#include "integrators/bidirectional/strategy_weight.h"

#include "integrators/bidirectional/path_density.h"

namespace caustica {

namespace {

// Densities through a delta lobe are stored as 0 on both sides of a ratio;
// reading them as 1 lets the discrete choices cancel.
float remap(float pdf) { return pdf != 0 ? pdf : 1; }

}  // namespace

ConnectionDensities connection_densities(const Scene& scene, std::span<const PathVertex> light,
                                         std::span<const PathVertex> camera, int s, int t) {
  ConnectionDensities d;
  if (s == 0) {
    d.camera_end = light_origin_density(scene, camera[t - 1]);
    if (t >= 2) d.camera_before_end = emission_density(camera[t - 1], camera[t - 2], camera[t - 2].chain_cos_bwd);
    return d;
  }
  if (t >= 2) {
    const DensityPair pair = scatter_densities(camera[t - 2], camera[t - 1], light[s - 1]);
    d.light_end = pair.to_next;
    d.camera_before_end = pair.to_prev;
  } else {
    d.light_end = scatter_density(scene, nullptr, camera[0], light[s - 1]);
  }
  if (s >= 2) {
    const DensityPair pair = scatter_densities(light[s - 2], light[s - 1], camera[t - 1]);
    d.camera_end = pair.to_next;
    d.light_before_end = pair.to_prev;
  } else {
    d.camera_end = scatter_density(scene, nullptr, light[0], camera[t - 1]);
  }
  return d;
}

ConnectionDensities joined_densities(const PathVertex& camera_prev, const PathVertex& camera_end,
                                     const ScatteringBothWays& at_camera, const PathVertex& light_prev,
                                     const PathVertex& light_end, const ScatteringBothWays& at_light) {
  const DensityPair camera_side =
      area_densities(camera_prev, camera_end, light_end, at_camera.forward, at_camera.backward);
  const DensityPair light_side = area_densities(light_prev, light_end, camera_end, at_light.forward, at_light.backward);
  return {.light_end = camera_side.to_next,
          .light_before_end = light_side.to_prev,
          .camera_end = light_side.to_next,
          .camera_before_end = camera_side.to_prev};
}

ConnectionDensities light_sample_densities(const Scene& scene, const PathVertex& camera_prev,
                                           const PathVertex& camera_end, const ScatteringBothWays& at_camera,
                                           const PathVertex& light) {
  const DensityPair camera_side = area_densities(camera_prev, camera_end, light, at_camera.forward, at_camera.backward);
  return {.light_end = camera_side.to_next,
          .camera_end = scatter_density(scene, nullptr, light, camera_end),
          .camera_before_end = camera_side.to_prev};
}

float strategy_weight(const Scene& scene, std::span<const PathVertex> light, std::span<const PathVertex> camera, int s,
                      int t, MisHeuristic heuristic) {
  return strategy_weight(light, camera, s, t, heuristic, connection_densities(scene, light, camera, s, t));
}

float strategy_weight(std::span<const PathVertex> light, std::span<const PathVertex> camera, int s, int t,
                      MisHeuristic heuristic, const ConnectionDensities& densities) {
  const int k = s + t - 1;  // the path has vertices x_0 (on the light) .. x_k (the camera)
  const auto [light_end, light_before_end, camera_end, camera_before_end] = densities;

  const PathVertex& origin = s > 0 ? light[0] : camera[k];
  const auto h = [&](float r) { return heuristic == MisHeuristic::Power ? r * r : r; };
  // Ratios of each other strategy's density to this one's, walking away
  // from the connection one vertex at a time. Strategy s' joins x_{s'-1}
  // to x_{s'}, so it is possible unless one of them scatters through a
  // delta lobe (the connection's own endpoints never do) or, for s' = 0, the
  // path starts on a delta light; a one-segment path from the camera to an
  // environment light has no strategy s' = 1.
  float sum = 1, r = 1;
  // Strategies s' > s: x_i = camera[k - i] for i >= s, whose density from
  // the light side is the connection's for i = s and s + 1.
  for (int i = s; i < k; ++i) {
    const int j = k - i;
    const float from_light = i == s ? camera_end : i == s + 1 ? camera_before_end : camera[j].pdf_rev;
    r *= remap(from_light) / remap(camera[j].pdf_fwd);
    const int sp = i + 1;
    const bool possible = sp == k && k == 1
                              ? !origin.environment && !origin.delta_light
                              : (i == 0 || i == s || !camera[j].delta) && (sp == k || !camera[j - 1].delta);
    if (possible) sum += h(r);
  }
  // Strategies s' < s: x_i = light[i], whose density from the camera side
  // is the connection's for i = s - 1 and s - 2.
  r = 1;
  for (int sp = s - 1; sp >= 0; --sp) {
    const float from_camera = sp == s - 1 ? light_end : sp == s - 2 ? light_before_end : light[sp].pdf_rev;
    r *= remap(from_camera) / remap(light[sp].pdf_fwd);
    const bool possible =
        sp == 0 ? !origin.delta_light : (sp == 1 || !light[sp - 1].delta) && (sp == s - 1 || !light[sp].delta);
    if (possible) sum += h(r);
  }
  return 1 / sum;
}

}  // namespace caustica
