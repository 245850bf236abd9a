#include "integrators/bidirectional/subpath.h"

#include "core/lights/spectral_emission.h"
#include "core/scene/scene.h"
#include "core/transport/light_path_start.h"
#include "core/transport/random_walk.h"
#include "integrators/bidirectional/path_density.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

// Records every vertex a walk reaches, in radiance mode also the
// environment it escapes to.
class SubpathRecorder {
 public:
  SubpathRecorder(const Scene& scene, TransportMode mode, std::vector<PathVertex>& path)
      : scene_(scene), mode_(mode), path_(path) {}

  WalkAction at_vertex(const WalkVertex& w) {
    PathVertex& v = path_.emplace_back();
    v.si = w.si;
    v.emitter = w.si.shape->emitter();
    v.beta = w.beta;
    v.bsdf.emplace(w.bsdf);
    v.medium = w.medium;
    return WalkAction::Continue;
  }

  // A free flight shorter than the float spacing at its origin puts the
  // event on the vertex before it, and no direction joins the two: their
  // densities would be 0 / 0. Such paths have measure zero in the path
  // integral, so the subpath ends there rather than carry a NaN into every
  // strategy built on it.
  WalkAction at_medium_vertex(const MediumVertex& m) {
    if (!path_.back().environment && m.p == path_.back().p()) return WalkAction::Stop;
    PathVertex& v = path_.emplace_back();
    v.kind = PathVertex::Kind::Medium;
    v.si.p = m.p;
    v.si.time = m.time;
    v.beta = m.beta;
    v.medium = &m.medium;
    return WalkAction::Continue;
  }

  WalkAction scattered_in_medium(const PhaseSample&) {
    path_.back().delta = false;
    return WalkAction::Continue;
  }

  void escaped(const WalkEscape& e) {
    if (mode_ != TransportMode::Radiance || scene_.infinite_emitters().empty()) return;
    PathVertex& v = path_.emplace_back();
    v.kind = PathVertex::Kind::Light;
    v.environment = true;
    v.w_env = e.ray.d;
    v.si.time = e.ray.time;
    v.beta = e.beta;
  }

  WalkAction scattered(const BsdfSample& bs) {
    path_.back().delta = bs.is_delta();
    return WalkAction::Continue;
  }

 private:
  const Scene& scene_;
  TransportMode mode_;
  std::vector<PathVertex>& path_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

void trace_camera_subpath(const Scene& scene, const Ray& ray, Sampler& sampler, const PathSettings& settings,
                          std::vector<PathVertex>& path, Wavelengths* wavelengths) {
  path.clear();
  if (settings.max_depth == 0) return;
  PathVertex& camera = path.emplace_back();
  camera.kind = PathVertex::Kind::Camera;
  camera.si.p = ray.o;
  camera.si.time = ray.time;
  camera.beta = Color(1);
  camera.medium = scene.sensor().medium();
  // Every camera's importance and the densities it samples rays with cancel
  // (pinhole, thin lens, orthographic): every camera ray carries weight one,
  // the filter's weight being the film's business.
  SubpathRecorder recorder(scene, TransportMode::Radiance, path);
  random_walk(scene, ray, Color(1), TransportMode::Radiance, camera_walk_limits(settings), sampler, recorder,
              camera.medium, wavelengths);
}

void trace_light_subpath(const Scene& scene, Sampler& sampler, float time, const PathSettings& settings,
                         std::vector<PathVertex>& path, Wavelengths* wavelengths) {
  path.clear();
  const auto start = start_light_path(scene, sampler, time);
  if (settings.max_depth == 0 || !start) return;

  PathVertex& light = path.emplace_back();
  light.kind = PathVertex::Kind::Light;
  light.emitter = start->emitter;
  light.delta_light = start->emitter->is_delta();
  light.medium = start->emitter->medium();
  light.si.time = time;  // a connection from the light's own point leaves at the path's time
  if (start->emitter->is_infinite()) {
    light.environment = true;
    light.w_env = -start->le.ray.d;
    light.beta = Color(1 / (start->pmf * start->le.pdf_dir));
  } else {
    light.si.p = start->le.ray.o;
    light.si.ng = start->le.n;
    light.si.uv = start->le.uv;  // where a textured emitter is read when joined to the camera
    if (light.has_normal()) light.si.shading = Frame::from_normal(start->le.n);
    light.beta = Color(1 / (start->pmf * start->le.pdf_pos));
  }
  SubpathRecorder recorder(scene, TransportMode::Importance, path);
  // The emitted weight is Le times a number, so lifting it lifts Le.
  random_walk(scene, start->le.ray, emission_for(*start->emitter, start->beta, wavelengths), TransportMode::Importance,
              light_walk_limits(settings), sampler, recorder, light.medium, wavelengths);
}

void compute_densities(const Scene& scene, std::vector<PathVertex>& path, MisHeuristic heuristic,
                       const Merging& merging) {
  const size_t n = path.size();
  if (n == 0) return;
  find_chain_ends(path);
  path[0].pdf_fwd = path[0].kind == PathVertex::Kind::Camera ? 1 : light_origin_density(scene, path[0]);
  if (n >= 2)
    path[1].pdf_fwd = path[0].delta ? 0 : scatter_density(scene, nullptr, path[0], path[1], path[1].chain_cos_fwd);
  path[n - 1].pdf_rev = 0;
  if (n >= 2) path[n - 2].pdf_rev = 0;
  // Each scattering vertex gives its successor's forward density and its
  // predecessor's reverse one.
  for (size_t j = 1; j + 1 < n; ++j) {
    if (path[j].delta) {
      path[j + 1].pdf_fwd = 0;
      path[j - 1].pdf_rev = 0;
      continue;
    }
    const DensityPair d = scatter_densities(path[j - 1], path[j], path[j + 1]);
    path[j + 1].pdf_fwd = d.to_next;
    path[j - 1].pdf_rev = d.to_prev;
  }
  sum_partial_ratios(path, heuristic, merging);
}

}  // namespace caustica
