// vcm: vertex connection and merging (Georgiev, Krivanek, Davidovic and
// Slusallek 2012). Each iteration traces one light subpath per pixel and
// keeps their vertices; every pixel then traces a camera subpath that
// joins the light subpath of its own index by every bdpt strategy and
// merges, at each of its vertices, with the kept light vertices of every
// light subpath within the iteration's radius (a photon map of the light
// subpaths). Merging finds what connections cannot, light reflected by a
// diffuse surface seen through glass (specular-diffuse-specular paths),
// and connections what merging finds badly; multiple importance sampling
// over both, with merging at x_i counted as a strategy of density
// p_{i+1} p_camera(x_i) N pi r^2, gives each path to the strategies that
// find it best. The radius shrinks over the iterations as in progressive
// photon mapping (radius_i^2 = radius_0^2 prod_{k<=i} (k + alpha) / (k + 1)),
// so the merges' bias vanishes as iterations add up.
//
// `mode` chooses the strategies: both (vcm), connect (the connections
// alone: bdpt, its light subpaths traced per iteration) or merge (the
// camera subpath's own emission hits and the merges: a progressive photon
// map gathered at every camera vertex). `merge_at` after_specular keeps
// only the merges at camera vertices reached through a delta lobe, the
// ones that find what no connection can; the weights leave the others out
// of every path's strategies. The weights are those of the full
// path's densities (strategy_weight.h), each subpath carrying the partial
// sums of their ratios as the paper's recursive form does, so that a
// connection or a merge costs the same for a long path as for a short one;
// a merge takes what needs the light vertex's scattering from the camera
// vertex within the radius, which stands in for it. Light subpath i of
// iteration n draws from (seed, n, i) and the light-tracing splats sum
// exactly, so the image does not depend on the thread count. In a moving scene an iteration's subpaths all live at its
// time (pass_time).
//
//   <integrator type="vcm"><string name="mode" value="both"/></integrator>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/film/film_buffer.h"
#include "core/film/splat_list.h"
#include "core/math/constants.h"
#include "core/registry/properties.h"
#include "core/render/camera_sample.h"
#include "core/render/iterative_integrator.h"
#include "core/render/pass_time.h"
#include "core/render/path_settings.h"
#include "core/scene/scene.h"
#include "integrators/bidirectional/camera_connection.h"
#include "integrators/bidirectional/connection.h"
#include "integrators/bidirectional/path_density.h"
#include "integrators/bidirectional/subpath.h"
#include "integrators/photon/photon_map.h"
#include "integrators/photon/photon_settings.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

enum class VcmMode { Both, Connect, Merge };

VcmMode read_mode(const Properties& props) {
  const std::string name = props.get_string("mode");
  if (name == "both") return VcmMode::Both;
  if (name == "connect") return VcmMode::Connect;
  if (name == "merge") return VcmMode::Merge;
  throw props.error("mode", "must be both, connect or merge, not '" + name + "'");
}

// Where merges may happen (Merging::after_delta_only).
bool read_after_delta_only(const Properties& props) {
  const std::string name = props.get_string("merge_at");
  if (name == "every_vertex") return false;
  if (name == "after_specular") return true;
  throw props.error("merge_at", "must be every_vertex or after_specular, not '" + name + "'");
}

class VertexConnectionMerging;

// A light-subpath vertex that merges may use.
struct KeptVertex {
  uint32_t path, vertex;
};

// What a block of light subpaths gives: the subpaths themselves, one after
// another in one array (the camera pass reads them in the same order, so
// that they stream through the cache rather than miss it a subpath at a
// time), its light-tracing splats and, where merges are made, the vertices
// they may use.
struct LightBlock {
  std::vector<PathVertex> subpaths;
  std::vector<uint32_t> starts;  // subpath j of the block: [starts[j], starts[j + 1])
  SplatList splats;
  std::vector<Photon> photons;
  std::vector<KeptVertex> vertices;
};

class VcmPixels final : public IterationState {
 public:
  VcmPixels(const VertexConnectionMerging& vcm, const Scene& scene, uint64_t seed);
  bool iterate(uint64_t iteration, const std::atomic<bool>* stop) override;
  Color estimate(Vec2i pixel) const override;
  std::string summary() const override;

 private:
  bool trace_light_subpaths(uint64_t iteration, const std::atomic<bool>* stop);
  void keep_vertices(size_t path, const std::vector<PathVertex>& light, LightBlock& block) const;
  std::span<const PathVertex> light_subpath(size_t path) const;
  void build_map(float radius);
  void camera_sample(Sampler& sampler, Vec2i pixel, uint64_t iteration, float radius);
  Color merge(const std::vector<PathVertex>& camera, int t, float radius) const;

  const VertexConnectionMerging& vcm_;
  const Scene& scene_;
  uint64_t seed_;
  int width_, height_;
  Merging merging_;
  // The camera subpaths' estimates, weighted by their filter weights, and
  // those weights (filter importance sampling: the pixel's estimate is
  // their weighted mean).
  std::vector<Color> camera_sums_;
  std::vector<double> filter_weights_;
  FilmBuffer light_image_;  // the light-tracing splats (t = 1)
  uint64_t iterations_ = 0;
  float radius_ = 0;
  // In a moving scene, the iteration's time: its light and camera subpaths
  // all live at it, so that merges and connections join one instant.
  std::optional<float> time_;
  size_t light_path_count_ = 0;  // one per pixel
  // Kept between iterations, so that their memory is reused.
  std::vector<LightBlock> blocks_;
  std::vector<Photon> kept_;
  std::vector<KeptVertex> kept_vertices_;
  PhotonMap map_;
};

class VertexConnectionMerging final : public IterativeIntegrator {
 public:
  explicit VertexConnectionMerging(const Properties& props)
      : settings_(read_path_settings(props)),
        heuristic_(read_mis_heuristic(props)),
        mode_(read_mode(props)),
        after_delta_only_(read_after_delta_only(props)),
        merge_(read_radius_schedule(props)) {
    if (after_delta_only_ && mode_ == VcmMode::Merge)
      throw props.error("merge_at",
                        "after_specular needs mode both: merging alone at those vertices would find no path that "
                        "passes no delta lobe (a point light's light reflected diffusely, say)");
  }

  std::unique_ptr<IterationState> begin(const Scene& scene, uint64_t seed) const override {
    return std::make_unique<VcmPixels>(*this, scene, seed);
  }

  bool renders_motion() const override { return true; }

  std::string plan(const Scene& scene) const override {
    const std::string radius = merge_.radius > 0 ? std::to_string(merge_.radius) : "1/200 of the scene's diagonal";
    const std::string where =
        after_delta_only_ ? "at the camera vertices reached through a delta lobe" : "at every camera vertex";
    std::string what = mode_ == VcmMode::Connect ? "every bdpt connection, no merging"
                       : mode_ == VcmMode::Merge ? "emission hits and merging " + where + ", no connections"
                                                 : "every bdpt connection and merging " + where;
    return "vcm: one light subpath per pixel and iteration; " + what + " (radius " + radius +
           " at first, shrinking with alpha " + std::to_string(merge_.alpha) + "), weighed by the " +
           (heuristic_ == MisHeuristic::Power ? "power" : "balance") + " heuristic" +
           (scene.features().caustic_paths && mode_ != VcmMode::Connect
                ? "; caustics seen through specular surfaces by merging"
                : "");
  }

 private:
  friend class VcmPixels;
  PathSettings settings_;
  MisHeuristic heuristic_;
  VcmMode mode_;
  bool after_delta_only_;
  PhotonSettings merge_;
};

// Light subpaths traced in blocks of this many, each block's splats kept in
// its own list.
constexpr size_t kBlock = 256;

VcmPixels::VcmPixels(const VertexConnectionMerging& vcm, const Scene& scene, uint64_t seed)
    : vcm_(vcm),
      scene_(scene),
      seed_(seed),
      width_(scene.sensor().film()->width()),
      height_(scene.sensor().film()->height()),
      camera_sums_(size_t(width_) * height_),
      filter_weights_(size_t(width_) * height_),
      light_image_(width_, height_, {"R", "G", "B"}, FilmBuffer::Moments::None) {
  light_image_.enable_splats();
  merging_.connections = vcm.mode_ != VcmMode::Merge;
  merging_.after_delta_only = vcm.after_delta_only_;
}

bool VcmPixels::iterate(uint64_t iteration, const std::atomic<bool>* stop) {
  radius_ = round_radius(vcm_.merge_, initial_radius(scene_, vcm_.merge_), uint32_t(iteration));
  light_path_count_ = size_t(width_) * height_;
  const double paths = double(light_path_count_);
  merging_.eta = vcm_.mode_ == VcmMode::Connect ? 0 : float(paths * kPi * double(radius_) * radius_);
  if (scene_.features().motion) time_ = pass_time(iteration, seed_);
  if (!trace_light_subpaths(iteration, stop)) return false;
  if (merging_.eta > 0) build_map(radius_);
  tbb::parallel_for(0, height_, [&](int y) {
    auto sampler = scene_.sensor().sampler()->clone();
    for (int x = 0; x < width_; ++x) camera_sample(*sampler, {x, y}, iteration, radius_);
  });
  for (const LightBlock& block : blocks_) {
    light_image_.add_splats(block.splats, scene_.sensor().film()->filter(), 0, height_);
    light_image_.record_dropped(block.splats);
  }
  light_image_.add_splat_paths(1);
  ++iterations_;
  return true;
}

// One per pixel, each joined to the camera (strategies t = 1).
bool VcmPixels::trace_light_subpaths(uint64_t iteration, const std::atomic<bool>* stop) {
  const PathSettings& settings = vcm_.settings_;
  const size_t blocks = (light_path_count_ + kBlock - 1) / kBlock;
  blocks_.resize(blocks);
  const auto stopped = [&] { return stop && stop->load(); };
  tbb::parallel_for(size_t(0), blocks, [&](size_t b) {
    if (stopped()) return;
    auto sampler = scene_.sensor().sampler()->clone();
    LightBlock& block = blocks_[b];
    SplatList& splats = block.splats;
    splats.clear();
    block.photons.clear();
    block.vertices.clear();
    block.subpaths.clear();
    block.starts.assign(1, 0);
    thread_local std::vector<PathVertex> light;
    for (size_t i = b * kBlock; i < std::min(light_path_count_, (b + 1) * kBlock); ++i) {
      sampler->start_sample(SampleKey::photon_round(iteration), i, seed_);
      trace_light_subpath(scene_, *sampler, time_.value_or(0), settings, light);
      compute_densities(scene_, light, vcm_.heuristic_, merging_);
      block.subpaths.insert(block.subpaths.end(), light.begin(), light.end());
      block.starts.push_back(uint32_t(block.subpaths.size()));
      if (merging_.eta > 0) keep_vertices(i, light, block);
      if (!merging_.connections) continue;
      for (int s = 1; s <= int(light.size()); ++s) {
        if ((s == 1 && settings.hide_emitters) || (settings.max_depth >= 0 && s > settings.max_depth)) continue;
        const auto c = connect_to_camera(scene_, light, s, *sampler);
        if (!c) continue;
        const std::span<const PathVertex> lens{&c->camera, 1}, part = std::span(light).first(s);
        splats.set_source({{int(i % size_t(width_)), int(i / size_t(width_))}, iteration});
        splats.add(c->raster, c->value * strategy_weight(part, lens, s, 1, vcm_.heuristic_,
                                                         connection_densities(scene_, part, lens, s, 1), merging_));
      }
    }
  });
  return !stopped();
}

// The vertices of light subpath `path` that merges may use: past the
// light's own, on a surface with a non-delta lobe, short enough to leave a
// camera segment.
void VcmPixels::keep_vertices(size_t path, const std::vector<PathVertex>& light, LightBlock& block) const {
  const int64_t max_depth = vcm_.settings_.max_depth;
  for (size_t v = 1; v < light.size(); ++v) {
    if (!mergeable(light[v]) || (max_depth >= 0 && int64_t(v) >= max_depth)) continue;
    Photon& ph = block.photons.emplace_back();
    ph.p = light[v].p();
    ph.wi = direction_to(light[v], light[v - 1]);
    ph.n = light[v].si.ng;
    ph.power = light[v].beta;
    ph.depth = uint32_t(v);
    block.vertices.push_back({uint32_t(path), uint32_t(v)});
  }
}

std::span<const PathVertex> VcmPixels::light_subpath(size_t path) const {
  const LightBlock& block = blocks_[path / kBlock];
  const size_t j = path % kBlock;
  return std::span(block.subpaths).subspan(block.starts[j], block.starts[j + 1] - block.starts[j]);
}

// The blocks' kept vertices, in block order, in a photon map.
void VcmPixels::build_map(float radius) {
  kept_.clear();
  kept_vertices_.clear();
  for (const LightBlock& block : blocks_) {
    for (Photon ph : block.photons) {
      ph.source = uint32_t(kept_.size());
      kept_.push_back(ph);
    }
    kept_vertices_.insert(kept_vertices_.end(), block.vertices.begin(), block.vertices.end());
  }
  map_.build(kept_, radius);
}

void VcmPixels::camera_sample(Sampler& sampler, Vec2i pixel, uint64_t iteration, float radius) {
  thread_local std::vector<PathVertex> camera;
  const PathSettings& settings = vcm_.settings_;
  const CameraSample cs = sample_camera_ray(scene_, sampler, pixel, iteration, seed_, time_);
  trace_camera_subpath(scene_, cs.ray, sampler, settings, camera);
  compute_densities(scene_, camera, vcm_.heuristic_, merging_);
  const std::span<const PathVertex> light = light_subpath(size_t(pixel.y) * width_ + pixel.x);
  const int max_s = merging_.connections ? int(light.size()) : 0;
  Color sum;
  for (int t = 2; t <= int(camera.size()); ++t) {
    for (int s = 0; s <= max_s; ++s) {
      const int k = s + t - 1;
      if ((settings.max_depth >= 0 && k > settings.max_depth) || (k == 1 && settings.hide_emitters)) continue;
      sum += connect(scene_, light, s, camera, t, sampler, nullptr, vcm_.heuristic_, merging_);
    }
    if (merging_.eta > 0) sum += merge(camera, t, radius);
  }
  const size_t p = size_t(pixel.y) * width_ + pixel.x;
  camera_sums_[p] += sum * cs.weight;
  filter_weights_[p] += cs.weight;
}

// Merging at camera[t-1] with the kept light vertices within the radius: a
// light subpath of s vertices ending there joins camera[t-2] as connection
// (s, t - 1) would, the camera subpath's own vertex standing in for its
// end, and its value is the photon density estimate's (photon_density.h).
Color VcmPixels::merge(const std::vector<PathVertex>& camera, int t, float radius) const {
  const PathVertex& cv = camera[t - 1];
  if ((merging_.after_delta_only && (t < 3 || !camera[t - 2].delta)) || !mergeable(cv)) return {};
  const int64_t max_depth = vcm_.settings_.max_depth;
  const Vec3 wo = direction_to(cv, camera[t - 2]);
  const std::span<const PathVertex> camera_part = std::span(camera).first(t - 1);
  // Most camera vertices find no photon: their densities only when one does.
  std::optional<DensityPair> camera_side;
  Color sum;
  map_.for_each_within(cv.p(), radius, [&](const Photon& ph) {
    if (max_depth >= 0 && int64_t(ph.depth) + t - 1 > max_depth) return;
    if (dot(ph.n, cv.si.ng) < 0.5f) return;
    const float cos_g = abs_dot(ph.wi, cv.si.ng);
    if (cos_g == 0) return;
    const ScatteringBothWays at_merge = scattering_both_ways(cv, wo, ph.wi);
    if (at_merge.f.is_black()) return;
    if (!camera_side) camera_side = merge_camera_densities(scene_, camera, t - 1);
    const KeptVertex kept = kept_vertices_[ph.source];
    const int s = int(kept.vertex) + 1;
    const std::span<const PathVertex> light = light_subpath(kept.path).first(size_t(s));
    const float w = merge_weight(light, camera_part, s, t - 1, vcm_.heuristic_,
                                 merge_densities(light, s, camera[t - 2], *camera_side, at_merge), merging_);
    sum += at_merge.f * ph.power * (w / cos_g);
  });
  return cv.beta * sum / merging_.eta;
}

Color VcmPixels::estimate(Vec2i pixel) const {
  const size_t p = size_t(pixel.y) * width_ + pixel.x;
  float light[3];
  light_image_.resolve_pixel(p, light);
  const Color camera = filter_weights_[p] != 0 ? camera_sums_[p] / float(filter_weights_[p]) : Color();
  return camera + Color(light[0], light[1], light[2]);
}

std::string VcmPixels::summary() const {
  char radius[32];
  std::snprintf(radius, sizeof radius, "%.6g", radius_);
  return "iterations=" + std::to_string(iterations_) + ", last radius=" + radius;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(
    VertexConnectionMerging, "integrator", "vcm",
    path_settings_params({{"mis", ParamType::String, "power", "MIS heuristic: power (exponent 2) or balance"},
                          {"mode", ParamType::String, "both",
                           "strategies: both (connections and merging), connect (bdpt's alone) or merge (emission "
                           "hits and merging: a progressive photon map)"},
                          {"merge_at", ParamType::String, "every_vertex",
                           "where camera vertices merge: every_vertex, or after_specular (only those the camera "
                           "subpath reached through a delta lobe: the merges that find caustics seen through glass "
                           "or in a mirror, at a fraction of the lookups)"},
                          {"radius", ParamType::Float, "0",
                           "initial merge radius; 0 for 1/200 of the scene's bounding-box diagonal"},
                          {"alpha", ParamType::Float, "0.75",
                           "how fast the radius shrinks: the share of its area each iteration keeps, in (0, 1)"}},
                         1),
    {});

}  // namespace caustica
