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

#include "core/registry/properties.h"
#include "integrators/bidirectional/subpath.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {

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
    compute_densities(*scene, path);
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

}  // namespace
}  // namespace caustica
