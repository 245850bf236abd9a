#include "integrators/bidirectional/subpath.h"

#include <algorithm>

#include "integrators/bidirectional/path_density.h"
#include "core/scene/scene.h"

namespace caustica {

namespace {

size_t vertices_for(int64_t max_depth, int64_t extra) {
  return max_depth < 0 ? SIZE_MAX : size_t(std::max<int64_t>(0, max_depth + extra));
}

// Extends `path` from its last vertex along `ray`, which carries `beta`.
void random_walk(const Scene& scene, Ray ray, Color beta, Sampler& sampler, TransportMode mode,
                 const SubpathLimits& limits, std::vector<PathVertex>& path) {
  Color throughput(1);
  float eta_scale = 1;
  while (path.size() < limits.max_vertices) {
    const auto si = scene.intersect(ray);
    if (!si) {
      if (mode == TransportMode::Radiance && !scene.infinite_emitters().empty()) {
        PathVertex& v = path.emplace_back();
        v.kind = PathVertex::Kind::Light;
        v.environment = true;
        v.w_env = ray.d;
        v.beta = beta;
      }
      return;
    }
    PathVertex& v = path.emplace_back();
    v.si = *si;
    v.emitter = si->shape->emitter();
    v.beta = beta;
    v.bsdf.emplace(*si->shape->bsdf(), *si, mode);
    if (path.size() == limits.max_vertices) return;

    const float u_lobe = sampler.next_1d();
    const auto bs = v.bsdf->sample(-ray.d, u_lobe, sampler.next_2d());
    if (!bs) return;
    v.delta = bs->is_delta();
    const Color weight = bs->f * (abs_dot(bs->wi, si->shading.n) / bs->pdf);
    beta *= weight;
    throughput *= weight;
    if (mode == TransportMode::Radiance && bs->is_transmission()) eta_scale *= bs->eta * bs->eta;
    ray = si->spawn(bs->wi);
    if (int64_t(path.size()) - 1 >= limits.rr_depth) {
      const float q = std::min(throughput.max_component() * eta_scale, limits.rr_max_survival);
      if (!(sampler.next_1d() < q)) return;
      beta *= 1 / q;
      throughput *= 1 / q;
    }
  }
}

}  // namespace

SubpathLimits camera_subpath_limits(int64_t max_depth, int64_t rr_depth, float rr_max_survival) {
  return {vertices_for(max_depth, 1), rr_depth, rr_max_survival};
}

SubpathLimits light_subpath_limits(int64_t max_depth, int64_t rr_depth, float rr_max_survival) {
  return {vertices_for(max_depth, 0), rr_depth, rr_max_survival};
}

void trace_camera_subpath(const Scene& scene, const Ray& ray, Sampler& sampler, const SubpathLimits& limits,
                          std::vector<PathVertex>& path) {
  path.clear();
  if (limits.max_vertices == 0) return;
  PathVertex& camera = path.emplace_back();
  camera.kind = PathVertex::Kind::Camera;
  camera.si.p = ray.o;
  camera.beta = Color(1);
  // A pinhole's importance and densities cancel: every camera ray carries
  // weight one, the filter's weight being the film's business.
  random_walk(scene, ray, Color(1), sampler, TransportMode::Radiance, limits, path);
}

void trace_light_subpath(const Scene& scene, Sampler& sampler, const SubpathLimits& limits,
                         std::vector<PathVertex>& path) {
  path.clear();
  float u_select = sampler.next_1d();
  const Vec2 u_pos = sampler.next_2d(), u_dir = sampler.next_2d();
  if (limits.max_vertices == 0) return;
  const auto choice = scene.light_selection().sample(u_select);
  if (!choice) return;
  const auto le = choice->emitter->sample_Le(u_pos, u_dir);
  if (!le || !(le->pdf_pos > 0) || !(le->pdf_dir > 0) || le->Le.is_black()) return;

  PathVertex& light = path.emplace_back();
  light.kind = PathVertex::Kind::Light;
  light.emitter = choice->emitter;
  light.delta_light = le->delta_position;
  if (choice->emitter->is_infinite()) {
    light.environment = true;
    light.w_env = -le->ray.d;
    light.beta = Color(1 / (choice->pmf * le->pdf_dir));
  } else {
    light.si.p = le->ray.o;
    light.si.ng = le->n;
    if (light.has_normal()) light.si.shading = Frame::from_normal(le->n);
    light.beta = Color(1 / (choice->pmf * le->pdf_pos));
  }
  const float cos = le->n == Vec3() ? 1 : abs_dot(le->n, le->ray.d);
  const Color beta = le->Le * (cos / (choice->pmf * le->pdf_pos * le->pdf_dir));
  random_walk(scene, le->ray, beta, sampler, TransportMode::Importance, limits, path);
}

void compute_densities(const Scene& scene, std::vector<PathVertex>& path) {
  const size_t n = path.size();
  for (size_t i = 0; i < n; ++i) {
    PathVertex& v = path[i];
    if (i == 0)
      v.pdf_fwd = v.kind == PathVertex::Kind::Camera ? 1 : light_origin_density(scene, v);
    else
      v.pdf_fwd = path[i - 1].delta ? 0 : scatter_density(scene, i >= 2 ? &path[i - 2] : nullptr, path[i - 1], v);
    v.pdf_rev = 0;
    if (i + 2 < n && !path[i + 1].delta) v.pdf_rev = scatter_density(scene, &path[i + 2], path[i + 1], v);
  }
}

}  // namespace caustica
