#include "integrators/bidirectional/path_density.h"

#include <cmath>
#include <stdexcept>

#include "core/media/medium.h"
#include "core/scene/scene.h"

namespace caustica {

float solid_angle_to_area(const PathVertex& from, const PathVertex& to, float pdf, float chain_cos) {
  if (chain_cos >= 0) return pdf * chain_cos;
  if (to.environment) return pdf;
  const Vec3 d = to.p() - from.p();
  const float dist2 = squared_length(d);
  if (dist2 == 0) return 0;
  const float cos = to.has_normal() ? abs_dot(to.si.ng, d) / std::sqrt(dist2) : 1;
  return pdf * cos / dist2;
}

namespace {
namespace CAUSTICA_UNITY_ID {

// A density per unit area across a bundle of parallel rays along d,
// converted to the density per unit area on the surface of `to`, or for a
// chain start into the chain's measure (with the cosine where it ends).
float parallel_to_area(const PathVertex& to, Vec3 d, float pdf_across, float chain_cos) {
  if (chain_cos >= 0) return pdf_across * chain_cos;
  return to.has_normal() ? pdf_across * abs_dot(to.si.ng, d) : pdf_across;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

float emission_density(const PathVertex& light, const PathVertex& next, float chain_cos) {
  float pdf_pos = 0, pdf_dir = 0;
  if (light.environment) {
    // Environment rays start on a disk facing their direction, so the
    // density of the point they reach is the disk's, projected.
    light.emitter->pdf_Le({next.p(), -light.w_env, kInfinity, 0, light.si.time}, {}, &pdf_pos, &pdf_dir);
    return parallel_to_area(next, light.w_env, pdf_pos, chain_cos);
  }
  light.emitter->pdf_Le({light.p(), direction_to(light, next), kInfinity, 0, light.si.time}, light.si.ng, &pdf_pos,
                        &pdf_dir);
  return solid_angle_to_area(light, next, pdf_dir, chain_cos);
}

float light_origin_density(const Scene& scene, const PathVertex& v) {
  const float pmf = scene.light_selection().pmf(v.emitter);
  float pdf_pos = 0, pdf_dir = 0;
  if (v.environment) {
    v.emitter->pdf_Le({{}, -v.w_env, kInfinity, 0, v.si.time}, {}, &pdf_pos, &pdf_dir);
    return pmf * pdf_dir;
  }
  v.emitter->pdf_Le({v.p(), v.si.ng, kInfinity, 0, v.si.time}, v.si.ng, &pdf_pos, &pdf_dir);
  return pmf * pdf_pos;
}

float scatter_density(const Scene& scene, const PathVertex* prev, const PathVertex& cur, const PathVertex& next,
                      float chain_cos) {
  switch (cur.kind) {
    case PathVertex::Kind::Camera: {
      float pdf_pos = 0, pdf_dir = 0;
      const Vec3 d = direction_to(cur, next);
      scene.sensor().pdf_We({cur.p(), d, kInfinity, 0, cur.si.time}, &pdf_pos, &pdf_dir);
      // Parallel rays spread over the film's area reach next's surface with
      // the film's density, projected.
      if (scene.sensor().delta_direction()) return parallel_to_area(next, d, pdf_pos, chain_cos);
      return solid_angle_to_area(cur, next, pdf_dir, chain_cos);
    }
    case PathVertex::Kind::Light:
      return emission_density(cur, next, chain_cos);
    case PathVertex::Kind::Surface:
    case PathVertex::Kind::Medium:
      break;
  }
  if (!prev) throw std::logic_error("a scattering vertex cannot start a subpath");
  const Vec3 w_prev = direction_to(cur, *prev), w_next = direction_to(cur, next);
  return solid_angle_to_area(
      cur, next, cur.in_medium() ? cur.medium->phase().eval(w_prev, w_next) : cur.bsdf->pdf(w_prev, w_next), chain_cos);
}

DensityPair scatter_densities(const PathVertex& prev, const PathVertex& cur, const PathVertex& next) {
  return scatter_densities(prev, cur, next, next.chain_cos_fwd);
}

DensityPair scatter_densities(const PathVertex& prev, const PathVertex& cur, const PathVertex& next,
                              float next_chain_cos) {
  if (!cur.is_surface() && !cur.in_medium()) throw std::logic_error("a subpath's end vertex does not scatter");
  const Vec3 w_prev = direction_to(cur, prev), w_next = direction_to(cur, next);
  float forward, backward;
  if (cur.in_medium()) {
    forward = cur.medium->phase().eval(w_prev, w_next);
    backward = cur.medium->phase().eval(w_next, w_prev);
  } else {
    const auto pdfs = cur.bsdf->pdfs(w_prev, w_next);
    forward = pdfs.forward;
    backward = pdfs.backward;
  }
  return area_densities(prev, cur, next, forward, backward, next_chain_cos);
}

DensityPair area_densities(const PathVertex& prev, const PathVertex& cur, const PathVertex& next, float forward,
                           float backward) {
  return area_densities(prev, cur, next, forward, backward, next.chain_cos_fwd);
}

DensityPair area_densities(const PathVertex& prev, const PathVertex& cur, const PathVertex& next, float forward,
                           float backward, float next_chain_cos) {
  return {solid_angle_to_area(cur, next, forward, next_chain_cos),
          solid_angle_to_area(cur, prev, backward, prev.chain_cos_bwd)};
}

namespace {
namespace CAUSTICA_UNITY_ID {

// The cosine at a chain's far end `end`, reached from the chain's last
// vertex: 1 for a direction (the environment) or a point without a surface.
// With it a chain weighs its two ends as a straight segment between them
// would: the sampled densities, each end's cosine, the distance cancelled.
float end_cos(const PathVertex& end, const PathVertex& last) {
  return end.has_normal() && !end.environment ? abs_dot(end.si.ng, direction_to(end, last)) : 1;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

void find_chain_ends(std::vector<PathVertex>& path) {
  const size_t n = path.size();
  float ahead = -1;  // the forward chain cosine of a specular vertex at i
  for (size_t i = n; i-- > 0;) {
    path[i].chain_cos_fwd = specular(path[i]) ? ahead : -1;
    if (i > 0 && specular(path[i - 1]) && !specular(path[i])) ahead = end_cos(path[i], path[i - 1]);
  }
  float behind = -1;
  for (size_t i = 0; i < n; ++i) {
    path[i].chain_cos_bwd = specular(path[i]) ? behind : -1;
    if (i + 1 < n && specular(path[i + 1]) && !specular(path[i])) behind = end_cos(path[i], path[i + 1]);
  }
}

}  // namespace caustica
