// A diffuse plane (albedo rho) lit by a spherical light (radiance Le, radius
// R, centre at height h): wherever the whole sphere is above the horizon it
// acts as a point source of intensity Le pi R^2, so the plane reflects
// L = rho Le R^2 h / d^3 at distance d from the centre. The same with a point
// light of intensity I: L = rho I h / (pi d^3), with no noise at all.
//
// Each point is a z-test at significance 0.1%, Sidak-corrected over the
// points and integrators tested; seeds are fixed. Light tracing and BDPT
// are tested on an image of the plane instead, region by region against the
// formula integrated over each pixel, with errors from independent runs.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <functional>

#include "core/registry/properties.h"
#include "core/render/pixel_integrator.h"
#include "tests/support/chi2.h"
#include "tests/support/independent_runs.h"
#include "tests/support/test_scenes.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

constexpr float kRho = 0.6f, kLe = 3.0f, kRadius = 0.25f, kHeight = 1.0f;

std::string plane_scene(const std::string& integrator, const std::string& light, int half_width = 10) {
  return "<scene version='3.0.0'>" + integrator + "<shape type='rectangle'><transform name='to_world'><scale value='" +
         std::to_string(half_width) +
         "'/></transform>"
         "<bsdf type='diffuse'><rgb name='reflectance' value='" +
         std::to_string(kRho) + "'/></bsdf></shape>" + light + "</scene>";
}

std::string sphere_light() {
  return "<shape type='sphere'><point name='center' x='0' y='0' z='" + std::to_string(kHeight) +
         "'/><float name='radius' value='" + std::to_string(kRadius) +
         "'/><emitter type='area'><rgb name='radiance' value='" + std::to_string(kLe) + "'/></emitter></shape>";
}

std::unique_ptr<Sampler> sampler() {
  const PluginInfo* info = Registry::instance().find("sampler", "independent");
  return std::dynamic_pointer_cast<Sampler>(info->create(Properties(*info, {"test", 1})))->clone();
}

// Radiance leaving the plane at (x, y) toward a ray cast straight down from
// just above it, estimated from n samples: mean and standard error.
// One estimate along `ray` by the scene file's per-pixel integrator.
void sample_along(const LoadedScene& scene, const Ray& ray, Sampler& s, std::span<float> out) {
  dynamic_cast<const PixelIntegrator&>(*scene.integrator).estimator(*scene, 0)->sample({0, 0}, ray, s, out);
}

std::pair<double, double> estimate(const LoadedScene& scene, float x, float y, int n) {
  auto s = sampler();
  double sum = 0, sum2 = 0;
  float out[3];
  for (int i = 0; i < n; ++i) {
    s->start_sample(SampleKey::camera({int(x * 100), int(y * 100)}), i, 0);
    sample_along(scene, {{x, y, 0.01f}, {0, 0, -1}}, *s, out);
    sum += out[0];
    sum2 += double(out[0]) * out[0];
  }
  const double mean = sum / n;
  return {mean, std::sqrt(std::max(0.0, sum2 / n - mean * mean) / (n - 1))};
}

const float kPoints[][2] = {{0, 0}, {0.5f, 0}, {0.3f, -0.7f}, {1.5f, 1}, {-3, 2}};

TEST(DirectLighting, SphereLightOnPlane) {
  const char* integrators[] = {"<integrator type='direct'/>",
                               "<integrator type='direct'><integer name='emitter_samples' value='0'/></integrator>",
                               "<integrator type='direct'><integer name='bsdf_samples' value='0'/></integrator>",
                               "<integrator type='path'><integer name='max_depth' value='2'/></integrator>"};
  const double z_critical = test::two_sided_z_critical(test::sidak_alpha(0.001, 4 * 5));
  for (const char* integrator : integrators) {
    const auto scene = test::scene_from_xml(plane_scene(integrator, sphere_light()));
    for (const auto& p : kPoints) {
      const double d = std::sqrt(p[0] * p[0] + p[1] * p[1] + kHeight * kHeight);
      const double expected = kRho * kLe * kRadius * kRadius * kHeight / (d * d * d);
      const auto [mean, se] = estimate(scene, p[0], p[1], 20000);
      EXPECT_LT(std::abs(mean - expected) / se, z_critical)
          << integrator << " at (" << p[0] << ", " << p[1] << "): " << mean << " +- " << se << ", expected "
          << expected;
    }
  }
}

// Radiance of the lit plane averaged over pixel (x, y), by the midpoint rule
// on an 8 x 8 grid of camera rays; `radiance` gives it at a point (x, y, 0).
double pixel_expectation(const Scene& scene, int x, int y, const std::function<double(double, double)>& radiance) {
  constexpr int n = 8;
  double sum = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Ray ray = scene.sensor().generate_ray({x + (i + 0.5f) / n, y + (j + 0.5f) / n}, {0.5f, 0.5f});
      // The plane is z = 0 in the world; the ray starts at the camera, the
      // origin of render space.
      const Vec3d o = scene.world_point(ray.o);
      const double t = -o.z / ray.d.z;
      sum += radiance(o.x + ray.d.x * t, o.y + ray.d.y * t);
    }
  return sum / (n * n);
}

double sphere_light_radiance(double x, double y) {
  const double d = std::sqrt(x * x + y * y + kHeight * kHeight);
  return kRho * kLe * kRadius * kRadius * kHeight / (d * d * d);
}

// 24x24 pixels looking straight down at the plane from 0.6 above it.
const char* kTopCamera =
    "<sensor type='perspective'><float name='fov' value='90'/><transform name='to_world'>"
    "<lookat origin='0.1, -0.2, 0.6' target='0.1, -0.2, 0' up='0, 1, 0'/></transform>"
    "<film type='hdrfilm'><integer name='width' value='24'/><integer name='height' value='24'/>"
    "<rfilter type='box'/></film></sensor>";

// The plane under `light`, seen from above by 24x24 pixels, rendered by each
// integrator (XML, samples per pixel): region means of independent runs
// against `radiance` averaged over the region's pixels, at 0.1% Sidak-
// corrected over regions and integrators.
void expect_regions_match(const std::string& light, const std::vector<std::pair<const char*, uint32_t>>& integrators,
                          const std::function<double(double, double)>& radiance, uint64_t seed,
                          int plane_half_width = 10) {
  const auto regions = test::grid_regions(24, 24, 4);
  constexpr int kRuns = 10;
  const double t_critical =
      test::two_sided_t_critical(test::sidak_alpha(0.001, int(integrators.size() * regions.size())), kRuns - 1);
  for (const auto& [integrator, spp] : integrators) {
    const auto scene = test::scene_from_xml(plane_scene(std::string(integrator) + kTopCamera, light, plane_half_width));
    const auto estimates = test::estimate_regions(scene, regions, spp, kRuns, seed += kRuns);
    for (size_t i = 0; i < regions.size(); ++i) {
      double expected = 0;
      const test::Region& g = regions[i];
      for (int y = g.lo.y; y < g.hi.y; ++y)
        for (int x = g.lo.x; x < g.hi.x; ++x) expected += pixel_expectation(*scene, x, y, radiance);
      expected /= (g.hi.x - g.lo.x) * (g.hi.y - g.lo.y);
      const double score = test::difference_score(estimates[i], {expected, 0, 0});
      EXPECT_LT(std::abs(score), t_critical) << integrator << " region " << i << ": " << estimates[i].mean << " +- "
                                             << estimates[i].standard_error << ", expected " << expected;
    }
  }
}

TEST(DirectLighting, SphereLightOnPlaneSeenByLightPaths) {
  // max_depth 2: the formula leaves out light the plane sends back to the
  // light's own (diffuse) surface.
  expect_regions_match(sphere_light(),
                       {{"<integrator type='ptracer'><integer name='max_depth' value='2'/></integrator>", 256},
                        {"<integrator type='bdpt'><integer name='max_depth' value='2'/></integrator>", 64},
                        {"<integrator type='bdpt'><integer name='max_depth' value='2'/><string name='mis' "
                         "value='balance'/></integrator>",
                         64}},
                       sphere_light_radiance, 0);
}

// A tiny light far away (a sun-like cone of 1e-8 sr) keeps its precision:
// the cone is sampled from its versine, never from a rounded cosine.
TEST(DirectLighting, TinyFarSphereLight) {
  const float radius = 0.01f, height = 100, Le = 1e8f;
  const auto scene = test::scene_from_xml(
      "<scene version='3.0.0'><integrator type='direct'/><shape type='rectangle'><transform name='to_world'>"
      "<scale value='1000'/></transform><bsdf type='diffuse'><rgb name='reflectance' value='" +
      std::to_string(kRho) + "'/></bsdf></shape><shape type='sphere'><point name='center' x='0' y='0' z='" +
      std::to_string(height) + "'/><float name='radius' value='" + std::to_string(radius) +
      "'/><emitter type='area'><rgb name='radiance' value='" + std::to_string(Le) + "'/></emitter></shape></scene>");
  const double z_critical = test::two_sided_z_critical(test::sidak_alpha(0.001, 2));
  for (const auto& p : {std::array<float, 2>{0, 0}, std::array<float, 2>{30, 40}}) {
    const double d = std::sqrt(p[0] * p[0] + p[1] * p[1] + height * height);
    const double expected = kRho * Le * radius * radius * height / (d * d * d);
    const auto [mean, se] = estimate(scene, p[0], p[1], 4000);
    const double rounding = 1e-4 * expected;  // float geometry at this scale
    EXPECT_LT(std::abs(mean - expected) / std::sqrt(se * se + rounding * rounding), z_critical)
        << mean << " +- " << se << ", expected " << expected;
  }
}

TEST(DirectLighting, PointLightIsExact) {
  const float intensity = 2.0f;
  const auto scene = test::scene_from_xml(plane_scene("<integrator type='direct'/>",
                                                      "<emitter type='point'><point name='position' x='0' y='0' z='1'/>"
                                                      "<rgb name='intensity' value='" +
                                                          std::to_string(intensity) + "'/></emitter>"));
  for (const auto& p : kPoints) {
    const double d = std::sqrt(p[0] * p[0] + p[1] * p[1] + 1);
    const double expected = kRho * intensity / (M_PI * d * d * d);
    const auto [mean, se] = estimate(scene, p[0], p[1], 16);
    EXPECT_NEAR(mean, expected, 1e-5 * expected);
    EXPECT_LT(se, 1e-6);
  }
}

// The same far from the origin, where float's spacing is 1: the light's
// position, written as a <point> with a fractional offset, keeps it, since
// points are read in double and moved next to the camera before rounding.
TEST(DirectLighting, PointLightFarFromTheOriginIsExact) {
  const double far = 1e7, lx = far + 0.3, ly = far - 0.2;
  char position[160];
  std::snprintf(position, sizeof position, "<point name='position' x='%.17g' y='%.17g' z='1'/>", lx, ly);
  const std::string shift = "<translate x='" + std::to_string(far) + "' y='" + std::to_string(far) + "'/>";
  const auto scene = test::scene_from_xml(
      "<scene version='3.0.0'><integrator type='direct'/>"
      "<sensor type='perspective'><transform name='to_world'><lookat origin='0, 0, 3' target='0, 0, 0' up='0, 1, 0'/>" +
      shift +
      "</transform></sensor>"
      "<shape type='rectangle'><transform name='to_world'><scale value='10'/>" +
      shift + "</transform><bsdf type='diffuse'><rgb name='reflectance' value='" + std::to_string(kRho) +
      "'/></bsdf></shape><emitter type='point'>" + position + "<rgb name='intensity' value='2'/></emitter></scene>");
  auto s = sampler();
  float out[3];
  for (const auto& p : kPoints) {
    const Vec3 o = scene->render_point({far + p[0], far + p[1], 0.01});
    sample_along(scene, {o, {0, 0, -1}}, *s, out);
    const double dx = far + p[0] - lx, dy = far + p[1] - ly;
    const double d = std::sqrt(dx * dx + dy * dy + 1);
    const double expected = kRho * 2 / (M_PI * d * d * d);
    EXPECT_NEAR(out[0], expected, 1e-4 * expected) << "at (" << p[0] << ", " << p[1] << ")";
  }
}

// A spot light at height 1 shining down (cutoff 40 degrees, full beam to 20):
// the plane reflects rho I f(theta) / (pi d^3) at distance d, with f 1
// within the beam, (40 - theta) / 20 between, 0 beyond. Exact for direct
// light; by regions of independent runs for light tracing and BDPT.
const char* kSpot =
    "<emitter type='spot'><rgb name='intensity' value='2'/><float name='cutoff_angle' value='40'/>"
    "<float name='beam_width' value='20'/><transform name='to_world'><lookat origin='0, 0, 1' target='0, 0, 0' "
    "up='0, 1, 0'/></transform></emitter>";

double spot_radiance(double x, double y) {
  const double r = std::sqrt(x * x + y * y), d = std::sqrt(r * r + 1), theta = std::atan(r) * 180 / M_PI;
  const double f = theta <= 20 ? 1 : theta >= 40 ? 0 : (40 - theta) / 20;
  return kRho * 2 * f / (M_PI * d * d * d);
}

TEST(DirectLighting, SpotLightFallsOffLinearlyInAngle) {
  const auto scene = test::scene_from_xml(plane_scene("<integrator type='direct'/>", kSpot));
  for (const float x : {0.0f, 0.3f, 0.5f, 0.7f, 0.8f, 1.0f}) {
    const auto [mean, se] = estimate(scene, x, 0.1f, 4);
    EXPECT_NEAR(mean, spot_radiance(x, 0.1), 1e-5) << x;
  }
}

// A texture projected by the spot (Mitsuba's mapping): looking down with
// image up +y, the spot's local x is world -x, so the plane point (X, Y)
// reads (u, v) = (1/2 - X / (2 tan 40), 1/2 + Y / (2 tan 40)); the checks
// holding (0, 0) and (1/2, 1/2) have colour0.
TEST(DirectLighting, SpotLightProjectsItsTexture) {
  const std::string spot =
      "<emitter type='spot'><rgb name='intensity' value='2'/><float name='cutoff_angle' value='40'/>"
      "<float name='beam_width' value='20'/><texture type='checkerboard' name='texture'><float name='color0' "
      "value='0.25'/><float name='color1' value='1.5'/></texture><transform name='to_world'><lookat origin='0, 0, 1' "
      "target='0, 0, 0' up='0, 1, 0'/></transform></emitter>";
  const auto scene = test::scene_from_xml(plane_scene("<integrator type='direct'/>", spot));
  for (const auto& [x, y] : {std::pair{-0.2f, -0.2f}, {0.2f, -0.2f}, {0.2f, 0.2f}, {-0.2f, 0.25f}}) {
    const double t = std::tan(40 * M_PI / 180), u = 0.5 - x / (2 * t), v = 0.5 + y / (2 * t);
    const double check = (u < 0.5) == (v < 0.5) ? 0.25 : 1.5;
    const auto [mean, se] = estimate(scene, x, y, 4);
    EXPECT_NEAR(mean, spot_radiance(x, y) * check, 1e-5) << x << " " << y;
  }
  // Projected onto a plane, a texture needs a cone narrower than a hemisphere.
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><emitter type='spot'><float name='cutoff_angle' value='90'/>"
                               "<texture type='checkerboard' name='texture'/></emitter></scene>"),
              testing::HasSubstr("parameter 'texture' of emitter 'spot': needs a cutoff_angle below 90 degrees"));
}

TEST(DirectLighting, SpotLightSeenByLightPaths) {
  expect_regions_match(kSpot,
                       {{"<integrator type='ptracer'><integer name='max_depth' value='2'/></integrator>", 64},
                        {"<integrator type='bdpt'><integer name='max_depth' value='2'/></integrator>", 16}},
                       spot_radiance, 100);
}

// A directional light travelling at 30 degrees to the plane's normal: the
// plane reflects rho E cos 30 / pi everywhere. Exact for direct light and
// for path (the bounce escapes into nothing); light paths start on a disk
// across the scene's bounds, so the plane is kept small enough (half-width
// 1, still wider than the view) for most of them to be seen.
const char* kDirectional =
    "<emitter type='directional'><vector name='direction' x='0.5' y='0' z='-0.8660254'/>"
    "<rgb name='irradiance' value='2'/></emitter>";

double directional_radiance(double, double) { return kRho * 2 * std::cos(M_PI / 6) / M_PI; }

TEST(DirectLighting, DirectionalLightIsExact) {
  for (const char* integrator :
       {"<integrator type='direct'/>", "<integrator type='path'><integer name='max_depth' value='3'/></integrator>"}) {
    const auto scene = test::scene_from_xml(plane_scene(integrator, kDirectional));
    for (const auto& p : kPoints) {
      const auto [mean, se] = estimate(scene, p[0], p[1], 16);
      EXPECT_NEAR(mean, directional_radiance(p[0], p[1]), 1e-5) << integrator;
      EXPECT_LT(se, 1e-6);
    }
  }
}

TEST(DirectLighting, DirectionalLightSeenByLightPaths) {
  expect_regions_match(kDirectional,
                       {{"<integrator type='ptracer'><integer name='max_depth' value='2'/></integrator>", 16},
                        {"<integrator type='bdpt'><integer name='max_depth' value='2'/></integrator>", 8},
                        {"<integrator type='bdpt'><integer name='max_depth' value='2'/><string name='mis' "
                         "value='balance'/></integrator>",
                         8},
                        {"<integrator type='sppm'><integer name='max_depth' value='2'/><integer name='photons' "
                         "value='20000'/></integrator>",
                         8}},
                       directional_radiance, 200, 1);
}

// An emitter with a radiance texture seen straight on: light paths joined
// to the camera read the texture where they left the surface, so ptracer
// and bdpt agree with path (which reads it where the camera ray lands),
// region by region over independent runs at 0.1 %, Sidak-corrected.
TEST(DirectLighting, TexturedEmitterSeenByLightPaths) {
  const std::string scene_start =
      std::string("<scene version='3.0.0'>") + kTopCamera +
      "<shape type='rectangle'><transform name='to_world'><scale value='3'/></transform><emitter type='area'>"
      "<texture type='checkerboard' name='radiance'><float name='color0' value='0.2'/><float name='color1' "
      "value='3'/><transform name='to_uv'><scale value='4'/></transform></texture></emitter></shape>";
  const auto regions = test::grid_regions(24, 24, 4);
  constexpr int kRuns = 10;
  const double t_critical =
      test::two_sided_t_critical(test::sidak_alpha(0.001, int(2 * regions.size())), 2 * kRuns - 2);
  const auto path = test::estimate_regions(test::scene_from_xml(scene_start + "<integrator type='path'/></scene>"),
                                           regions, 16, kRuns, 300);
  for (const char* integrator : {"<integrator type='ptracer'><integer name='max_depth' value='1'/></integrator>",
                                 "<integrator type='bdpt'><integer name='max_depth' value='1'/></integrator>"}) {
    const auto other =
        test::estimate_regions(test::scene_from_xml(scene_start + integrator + "</scene>"), regions, 16, kRuns, 400);
    for (size_t i = 0; i < regions.size(); ++i)
      EXPECT_LT(std::abs(test::difference_score(other[i], path[i])), t_critical)
          << integrator << " region " << i << ": " << other[i].mean << " +- " << other[i].standard_error << ", path "
          << path[i].mean << " +- " << path[i].standard_error;
  }
}

// Three lights of different power and size over the plane: two sphere
// lights (the point-source formula above holds for each, the whole sphere
// being above the horizon) and a point light. Their contributions add, and
// light selection by power must weigh each consistently wherever it enters
// an estimator (next-event estimation, MIS for BSDF-sampled hits, light
// paths, photons). max_depth 2 keeps light the spheres reflect out of it;
// in view no light shadows another.
const char* kThreeLights =
    "<shape type='sphere'><point name='center' x='0.5' y='0' z='1.2'/><float name='radius' value='0.15'/>"
    "<emitter type='area'><rgb name='radiance' value='4'/></emitter></shape>"
    "<shape type='sphere'><point name='center' x='-0.4' y='0.3' z='0.8'/><float name='radius' value='0.3'/>"
    "<emitter type='area'><rgb name='radiance' value='1'/></emitter></shape>"
    "<emitter type='point'><point name='position' x='0.2' y='-0.5' z='1.5'/><rgb name='intensity' value='1.5'/>"
    "</emitter>";

double three_lights_radiance(double x, double y) {
  const auto sphere = [&](double cx, double cy, double h, double r, double Le) {
    const double d = std::sqrt((x - cx) * (x - cx) + (y - cy) * (y - cy) + h * h);
    return kRho * Le * r * r * h / (d * d * d);
  };
  const double dx = x - 0.2, dy = y + 0.5, d = std::sqrt(dx * dx + dy * dy + 1.5 * 1.5);
  return sphere(0.5, 0, 1.2, 0.15, 4) + sphere(-0.4, 0.3, 0.8, 0.3, 1) + kRho * 1.5 * 1.5 / (M_PI * d * d * d);
}

TEST(DirectLighting, SeveralLightsOfDifferentPower) {
  expect_regions_match(
      kThreeLights,
      {{"<integrator type='direct'/>", 16},
       {"<integrator type='path'><integer name='max_depth' value='2'/></integrator>", 16},
       {"<integrator type='ptracer'><integer name='max_depth' value='2'/></integrator>", 256},
       {"<integrator type='bdpt'><integer name='max_depth' value='2'/></integrator>", 16},
       {"<integrator type='bdpt'><integer name='max_depth' value='2'/><string name='mis' value='balance'/>"
        "</integrator>",
        16},
       {"<integrator type='photon'><integer name='max_depth' value='2'/></integrator>", 16},
       {"<integrator type='sppm'><integer name='max_depth' value='2'/><integer name='photons' value='20000'/>"
        "</integrator>",
        32}},
      three_lights_radiance, 500);
}

TEST(DirectLighting, EmittersSeenDirectlyAndHidden) {
  const auto shown = test::scene_from_xml(plane_scene("<integrator type='direct'/>", sphere_light()));
  const auto hidden = test::scene_from_xml(plane_scene(
      "<integrator type='direct'><boolean name='hide_emitters' value='true'/></integrator>", sphere_light()));
  auto s = sampler();
  float out[3];
  const Ray down{{0, 0, 2}, {0, 0, -1}};
  s->start_sample(SampleKey::camera({0, 0}), 0, 0);
  sample_along(shown, down, *s, out);
  EXPECT_FLOAT_EQ(out[0], kLe);
  s->start_sample(SampleKey::camera({0, 0}), 0, 0);
  sample_along(hidden, down, *s, out);
  EXPECT_FLOAT_EQ(out[0], 0);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
