#include "integrators/bidirectional/strategy_weight.h"

#include "integrators/bidirectional/path_density.h"

namespace caustica {

namespace {

// Densities through a delta lobe are stored as 0 on both sides of a ratio;
// reading them as 1 lets the discrete choices cancel.
float remap(float pdf) { return pdf != 0 ? pdf : 1; }

}  // namespace

float strategy_weight(const Scene& scene, std::span<const PathVertex> light, std::span<const PathVertex> camera, int s,
                      int t, MisHeuristic heuristic) {
  const int k = s + t - 1;  // the path has vertices x_0 (on the light) .. x_k (the camera)

  // The densities the connection decides: for x_{s-1} and x_{s-2} as the
  // camera side would sample them, for x_s and x_{s+1} as the light side would.
  float light_end = 0, light_before_end = 0, camera_end = 0, camera_before_end = 0;
  const PathVertex* camera_prev = t >= 2 ? &camera[t - 2] : nullptr;
  if (s == 0) {
    camera_end = light_origin_density(scene, camera[t - 1]);
    if (t >= 2) camera_before_end = emission_density(camera[t - 1], camera[t - 2]);
  } else {
    light_end = scatter_density(scene, camera_prev, camera[t - 1], light[s - 1]);
    if (s >= 2) light_before_end = scatter_density(scene, &camera[t - 1], light[s - 1], light[s - 2]);
    camera_end = scatter_density(scene, s >= 2 ? &light[s - 2] : nullptr, light[s - 1], camera[t - 1]);
    if (t >= 2) camera_before_end = scatter_density(scene, &light[s - 1], camera[t - 1], camera[t - 2]);
  }

  const auto vertex = [&](int i) -> const PathVertex& { return i < s ? light[i] : camera[k - i]; };
  // Density of x_i sampled from the light side, and from the camera side.
  const auto from_light = [&](int i) {
    if (i < s) return light[i].pdf_fwd;
    if (i == s) return camera_end;
    if (i == s + 1) return camera_before_end;
    return camera[k - i].pdf_rev;
  };
  const auto from_camera = [&](int i) {
    if (i >= s) return camera[k - i].pdf_fwd;
    if (i == s - 1) return light_end;
    if (i == s - 2) return light_before_end;
    return light[i].pdf_rev;
  };
  // Whether the path scatters at x_i through a delta lobe; the connection's
  // endpoints scatter through the connection, never a delta lobe.
  const auto scatters_delta = [&](int i) { return i != s - 1 && i != s && vertex(i).delta; };
  const PathVertex& origin = vertex(0);
  // Whether strategy s' (connecting x_{s'-1} to x_{s'}) could sample the path.
  const auto possible = [&](int sp) {
    if (sp == 0) return !origin.delta_light;
    if (sp == k && k == 1) return !origin.environment && !origin.delta_light;
    const bool left = sp - 1 == 0 || !scatters_delta(sp - 1);
    const bool right = sp == k || !scatters_delta(sp);
    return left && right;
  };
  const auto h = [&](float r) { return heuristic == MisHeuristic::Power ? r * r : r; };

  // Ratios of each other strategy's density to this one's, walking away
  // from the connection one vertex at a time.
  float sum = 1, r = 1;
  for (int sp = s + 1; sp <= k; ++sp) {
    r *= remap(from_light(sp - 1)) / remap(from_camera(sp - 1));
    if (possible(sp)) sum += h(r);
  }
  r = 1;
  for (int sp = s - 1; sp >= 0; --sp) {
    r *= remap(from_camera(sp)) / remap(from_light(sp));
    if (possible(sp)) sum += h(r);
  }
  return 1 / sum;
}

}  // namespace caustica
