// The density bdpt gives the first vertex of a camera subpath is the one
// the camera sampled it with, per unit area of the surface it lies on,
// written out from each camera's geometry: a pinhole or thin lens (fov 90
// on a square film: the window's area on the plane at distance 1 is 4)
// sends a ray at angle theta to its axis with solid-angle density
// 1 / (4 cos^3 theta), which a point at distance d whose surface is at
// angle theta_x to the ray receives as cos theta_x / (4 cos^3 theta d^2);
// the orthographic film (scaled to 1 x 1) gives cos theta_x / 1.

#include "integrators/bidirectional/path_density.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <utility>

#include "core/loader/scene_loader.h"
#include "core/registry/properties.h"
#include "integrators/bidirectional/subpath.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

LoadedScene tilted_plane_under(const std::string& sensor) {
  return test::scene_from_xml(
      "<scene version='3.0.0'>" + sensor +
      "<shape type='rectangle'><transform name='to_world'><scale value='5'/><rotate x='1' angle='25'/></transform>"
      "</shape><emitter type='constant'/></scene>");
}

std::string sensor(const std::string& type, const std::string& extra, const std::string& placement = "") {
  return "<sensor type='" + type + "'>" + extra + "<transform name='to_world'>" + placement +
         "<lookat origin='0.3, -0.2, 2' target='0, 0, 0' up='0, 1, 0'/></transform>"
         "<film type='hdrfilm'><integer name='width' value='16'/><integer name='height' value='16'/></film>"
         "</sensor>";
}

// The densities of camera subpaths' first surface vertices against
// `expected`(ray, hit).
template <class Expected>
void expect_first_vertex_densities(const LoadedScene& scene, Expected&& expected) {
  const PluginInfo* info = Registry::instance().find("sampler", "independent");
  auto sampler = std::dynamic_pointer_cast<Sampler>(info->create(Properties(*info, {"test", 1})))->clone();
  const PathSettings settings{1, 5, 0.95f, 0.1f, false};
  std::mt19937 rng(4);
  std::uniform_real_distribution<float> u(0, 1);
  std::vector<PathVertex> path;
  int checked = 0;
  for (int i = 0; i < 200; ++i) {
    sampler->start_sample(SampleKey::camera({0, 0}), uint64_t(i), 3);
    const Ray ray = scene->sensor().generate_ray({u(rng) * 16, u(rng) * 16}, {u(rng), u(rng)});
    trace_camera_subpath(*scene, ray, *sampler, settings, path);
    compute_densities(*scene, path, MisHeuristic::Power);
    if (path.size() < 2 || path[1].environment) continue;
    const double want = expected(ray, path[1]);
    EXPECT_NEAR(path[1].pdf_fwd, want, 1e-3 * want) << "sample " << i;
    ++checked;
  }
  EXPECT_GT(checked, 150);
}

TEST(PathDensity, PerspectiveAndThinLensCameraVertices) {
  for (const std::string& s : {sensor("perspective", "<float name='fov' value='90'/>"),
                               sensor("thinlens",
                                      "<float name='fov' value='90'/><float name='aperture_radius' value='0.2'/>"
                                      "<float name='focus_distance' value='1.5'/>")}) {
    const auto scene = tilted_plane_under(s);
    const Vec3 forward = scene->sensor().generate_ray({8, 8}, {0.5f, 0.5f}).d;
    expect_first_vertex_densities(scene, [&](const Ray& ray, const PathVertex& hit) {
      const double cos_theta = dot(ray.d, forward), d2 = squared_length(hit.p() - ray.o);
      return abs_dot(hit.si.ng, ray.d) / (4 * cos_theta * cos_theta * cos_theta * d2);
    });
  }
}

TEST(PathDensity, OrthographicCameraVertices) {
  const auto scene = tilted_plane_under(sensor("orthographic", "", "<scale x='0.5' y='0.5'/>"));
  expect_first_vertex_densities(scene, [](const Ray& ray, const PathVertex& hit) { return abs_dot(hit.si.ng, ray.d); });
}

// The cosine at the far end of the specular chain that starts at path[j]
// and runs on by `step` (+1 or -1): the first vertex that is not specular,
// at the direction back to the chain, 1 for the environment or a point
// without a normal; -1 when the chain runs off the path or path[j] is in
// no chain.
float chain_end_cos(const std::vector<PathVertex>& path, size_t j, int step) {
  if (!specular(path[j])) return -1;
  long k = long(j);
  while (k >= 0 && k < long(path.size()) && specular(path[size_t(k)])) k += step;
  if (k < 0 || k >= long(path.size())) return -1;
  const PathVertex &end = path[size_t(k)], &last = path[size_t(k - step)];
  if (end.environment || !end.has_normal()) return 1;
  return std::abs(dot(end.si.ng, normalize(last.p() - end.p())));
}

// The densities both ways at a scattering vertex are scatter_density's
// each way, bit for bit (as are a connection end's value and densities
// from scattering_both_ways: scattering's value, the same densities), and
// the subpaths' stored densities are the ones
// scatter_density and light_origin_density define, measured at the far
// end of a specular chain for a vertex that starts one: through diffuse,
// glossy, plastic, glass, mirror and participating-media vertices, on
// camera and light subpaths alike.
TEST(PathDensity, StoredDensitiesAreTheDefinedOnes) {
  const PluginInfo* info = Registry::instance().find("sampler", "independent");
  auto sampler = std::dynamic_pointer_cast<Sampler>(info->create(Properties(*info, {"test", 1})))->clone();
  const PathSettings settings{12, 5, 0.95f, 0.1f, false};
  std::vector<std::pair<std::string, LoadedScene>> scenes;
  for (const char* name : {"cornell-box-glossy", "cornell-box-phong", "cornell-box-glass-fog", "cornell-box-mirror"})
    scenes.emplace_back(name,
                        load_scene(std::string(CAUSTICA_SOURCE_DIR) + "/scenes/" + name + ".xml", {{"res", "16"}}));
  // Smooth plastic: vertices that leave through the delta coat still have
  // the diffuse base's density, which must not be stored; and glass whose
  // chains end in the environment.
  scenes.emplace_back(
      "plastic",
      test::scene_from_xml(
          "<scene version='3.0.0'>" + sensor("perspective", "<float name='fov' value='60'/>") +
          "<shape type='rectangle'><transform name='to_world'><scale value='3'/></transform><bsdf type='plastic'/>"
          "</shape><shape type='sphere'><float name='radius' value='0.4'/><bsdf type='plastic'/></shape>"
          "<shape type='sphere'><point name='center' x='0.5' y='0.5' z='1.5'/><float name='radius' value='0.3'/>"
          "<emitter type='area'><rgb name='radiance' value='5'/></emitter></shape>"
          "<shape type='sphere'><point name='center' x='-0.7' y='0' z='0.4'/><float name='radius' value='0.4'/>"
          "<bsdf type='dielectric'/></shape><emitter type='constant'><rgb name='radiance' value='0.5'/></emitter>"
          "</scene>"));
  int scattering = 0, in_medium = 0, delta = 0, chains = 0, to_environment = 0;
  for (const auto& [name, scene] : scenes) {
    std::vector<PathVertex> path;
    for (int i = 0; i < 1000; ++i) {
      sampler->start_sample(SampleKey::camera({i % 16, i / 16 % 16}), uint64_t(i), 5);
      if (i % 2)
        trace_light_subpath(*scene, *sampler, 0, settings, path);
      else
        trace_camera_subpath(*scene, scene->sensor().generate_ray({i % 16 + 0.5f, i / 16 % 16 + 0.5f}, {0.5f, 0.5f}),
                             *sampler, settings, path);
      compute_densities(*scene, path, MisHeuristic::Power);
      const size_t n = path.size();
      for (size_t j = 0; j < n; ++j) {
        const PathVertex& v = path[j];
        const float fwd = j == 0 ? (v.kind == PathVertex::Kind::Camera ? 1 : light_origin_density(*scene, v))
                          : path[j - 1].delta ? 0
                                              : scatter_density(*scene, j >= 2 ? &path[j - 2] : nullptr, path[j - 1], v,
                                                                chain_end_cos(path, j, 1));
        const float rev = j + 2 < n && !path[j + 1].delta
                              ? scatter_density(*scene, &path[j + 2], path[j + 1], v, chain_end_cos(path, j, -1))
                              : 0;
        chains += chain_end_cos(path, j, 1) >= 0 && chain_end_cos(path, j, -1) >= 0;
        to_environment += specular(v) && path.back().environment && chain_end_cos(path, j, 1) >= 0;
        EXPECT_EQ(v.pdf_fwd, fwd) << name << ", sample " << i << ", vertex " << j;
        EXPECT_EQ(v.pdf_rev, rev) << name << ", sample " << i << ", vertex " << j;
        delta += v.delta && v.is_surface() && (v.bsdf->lobes() & ~kDelta);
        if (j == 0 || j + 1 == n) continue;
        const DensityPair both = scatter_densities(path[j - 1], v, path[j + 1]);
        EXPECT_EQ(both.to_next, scatter_density(*scene, &path[j - 1], v, path[j + 1], chain_end_cos(path, j + 1, 1)))
            << name << ", vertex " << j;
        EXPECT_EQ(both.to_prev, scatter_density(*scene, &path[j + 1], v, path[j - 1], chain_end_cos(path, j - 1, -1)))
            << name << ", vertex " << j;
        // A connection's endpoint: the value and both densities from one call.
        const Vec3 w_prev = direction_to(v, path[j - 1]), w_next = direction_to(v, path[j + 1]);
        const ScatteringBothWays joined = scattering_both_ways(v, w_prev, w_next);
        const Color f = caustica::scattering(v, w_prev, w_next);
        EXPECT_TRUE(joined.f.r == f.r && joined.f.g == f.g && joined.f.b == f.b) << name << ", vertex " << j;
        const DensityPair from_joined = area_densities(path[j - 1], v, path[j + 1], joined.forward, joined.backward);
        EXPECT_EQ(from_joined.to_next, both.to_next) << name << ", vertex " << j;
        EXPECT_EQ(from_joined.to_prev, both.to_prev) << name << ", vertex " << j;
        ++scattering;
        in_medium += v.in_medium();
      }
    }
  }
  EXPECT_GT(scattering, 1000);
  EXPECT_GT(in_medium, 50);
  EXPECT_GT(delta, 50);
  EXPECT_GT(chains, 50);
  EXPECT_GT(to_environment, 20);
}

// `first` for the first number a sample draws, `rest` for every later one:
// with rest = 1e-9 each free flight after the first is about 1e-9 / sigma_t
// long, below the float spacing at its origin.
class ScriptedSampler final : public Sampler {
 public:
  ScriptedSampler(float first, float rest) : Sampler(1), first_(first), rest_(rest) {}
  std::unique_ptr<Sampler> clone() const override { return std::make_unique<ScriptedSampler>(first_, rest_); }
  void start_sample(SampleKey, uint64_t, uint64_t) override { drawn_ = false; }
  float next_1d() override { return std::exchange(drawn_, true) ? rest_ : first_; }
  Vec2 next_2d() override {
    const float a = next_1d();
    return {a, next_1d()};
  }

 private:
  float first_, rest_;
  bool drawn_ = false;
};

void expect_distinct_vertices_and_finite_densities(const std::vector<PathVertex>& path) {
  for (size_t i = 0; i < path.size(); ++i) {
    EXPECT_TRUE(std::isfinite(path[i].pdf_fwd)) << i;
    EXPECT_TRUE(std::isfinite(path[i].pdf_rev)) << i;
    if (i > 0) {
      EXPECT_NE(path[i].p(), path[i - 1].p()) << i;
    }
  }
}

TEST(PathDensity, AScatteringEventOnThePreviousVertexEndsTheSubpath) {
  // The camera and a point light inside a fog ball. The camera subpath's
  // first free flight (drawn with 0.3) goes 0.18 on, the next (1e-9) rounds
  // back onto that vertex; the light subpath's first rounds onto the light.
  const auto scene = test::scene_from_xml(
      "<scene version='3.0.0'><medium type='homogeneous' id='fog'><float name='sigma_t' value='2'/>"
      "<float name='albedo' value='0.8'/></medium>"
      "<sensor type='perspective'><ref id='fog'/><transform name='to_world'>"
      "<lookat origin='0.7, 0.6, 0.5' target='0, 0, 0'/></transform>"
      "<film type='hdrfilm'><integer name='width' value='4'/><integer name='height' value='4'/></film></sensor>"
      "<shape type='sphere'><float name='radius' value='2'/><ref name='interior' id='fog'/></shape>"
      "<emitter type='point'><point name='position' x='0.4' y='0.3' z='-0.6'/><rgb name='intensity' value='1'/>"
      "<ref id='fog'/></emitter></scene>");
  const PathSettings settings{8, 5, 0.95f, 0.1f, false};
  const Ray ray = scene->sensor().generate_ray({2, 2}, {0.5f, 0.5f});
  std::vector<PathVertex> camera, light;
  for (const float rest : {1e-9f, 0.3f}) {
    ScriptedSampler sampler(0.3f, rest);
    sampler.start_sample(SampleKey::camera({2, 2}), 0, 0);
    trace_camera_subpath(*scene, ray, sampler, settings, camera);
    compute_densities(*scene, camera, MisHeuristic::Power);
    expect_distinct_vertices_and_finite_densities(camera);
    sampler.start_sample(SampleKey::light_path({2, 2}), 0, 0);
    trace_light_subpath(*scene, sampler, 0, settings, light);
    compute_densities(*scene, light, MisHeuristic::Power);
    expect_distinct_vertices_and_finite_densities(light);
    // With 0.3 throughout, flights of 0.18 scatter on to the length limit.
    const size_t expected_camera = rest > 0.1f ? 9 : 2, expected_light = rest > 0.1f ? 8 : 1;
    EXPECT_EQ(camera.size(), expected_camera) << rest;
    EXPECT_EQ(light.size(), expected_light) << rest;
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
