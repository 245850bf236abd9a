// The projector (Mitsuba 3's projection light), the perspective camera's
// reciprocal: a plane facing it at distance D receives pi scale T(u, v) / D^2,
// so a diffuse plane of albedo rho shows rho scale T / D^2, the image
// undistorted. Checked exactly for direct light, by regions of independent
// runs for light tracing and BDPT, and its flux against its power.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "core/math/constants.h"
#include "core/registry/properties.h"
#include "core/render/pixel_integrator.h"
#include "tests/support/chi2.h"
#include "tests/support/independent_runs.h"
#include "tests/support/test_scenes.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using ::testing::HasSubstr;

constexpr double kRho = 0.6, kScale = 0.5;

// A diffuse plane z = 0 of albedo kRho under a projector at height 1 looking
// straight down (image up +y), seen by `camera`.
std::string scene_xml(const std::string& integrator, const std::string& camera, const std::string& irradiance,
                      const std::string& fov) {
  return "<scene version='3.0.0'>" + integrator + camera +
         "<shape type='rectangle'><transform name='to_world'><scale value='10'/></transform><bsdf type='diffuse'>"
         "<rgb name='reflectance' value='" +
         std::to_string(kRho) + "'/></bsdf></shape><emitter type='projector'>" + irradiance +
         "<float name='scale' value='" + std::to_string(kScale) + "'/><float name='fov' value='" + fov +
         "'/><transform name='to_world'><lookat origin='0, 0, 1' target='0, 0, 0' up='0, 1, 0'/></transform>"
         "</emitter></scene>";
}

// A 4x2 image of distinct texels, read raw: texel (i, j) holds (1 + i + 4 j) * 20 / 255.
std::filesystem::path slide() {
  const auto path = std::filesystem::temp_directory_path() / "caustica_projector_slide.ppm";
  std::ofstream out(path, std::ios::binary);
  out << "P6\n4 2\n255\n";
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 4; ++i)
      for (int c = 0; c < 3; ++c) out.put(char((1 + i + 4 * j) * 20));
  return path;
}

// A camera where the projector stands, with its field of view and a film of
// the slide's shape, sees the slide: pixel (i, j) shows texel (i, j), at
// rho scale T (D = 1). The frame's aspect comes from the image's (4:2);
// nearest texels and a box filter make every sample of a pixel read one
// texel, so direct light gives it exactly.
TEST(Projector, ItsOwnCameraSeesTheSlide) {
  const std::string camera =
      "<sensor type='perspective'><float name='fov' value='60'/><transform name='to_world'><lookat origin='0, 0, 1' "
      "target='0, 0, 0' up='0, 1, 0'/></transform><film type='hdrfilm'><integer name='width' value='4'/>"
      "<integer name='height' value='2'/><rfilter type='box'/></film></sensor>";
  const std::string irradiance = "<texture type='bitmap' name='irradiance'><string name='filename' value='" +
                                 slide().string() +
                                 "'/><boolean name='raw' value='true'/><string name='filter_type' "
                                 "value='nearest'/></texture>";
  const auto scene = test::scene_from_xml(scene_xml("<integrator type='direct'/>", camera, irradiance, "60"));
  const FilmBuffer film = test::render_scene(scene, 16, 3, 1);
  const std::vector<float> pixels = film.resolve();
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 4; ++i) {
      const double expected = kRho * kScale * (1 + i + 4 * j) * 20 / 255.0;
      EXPECT_NEAR(pixels[(j * 4 + i) * film.channel_count()], expected, 1e-5 * expected) << i << " " << j;
    }
}

// A checkerboard (no resolution: a square frame) through a 60 degree
// projector: the plane point (X, Y) is the local direction (-X, Y, 1), which
// reads (u, v) = ((1 + X / tan 30) / 2, (1 - Y / tan 30) / 2); outside the
// frame nothing arrives.
TEST(Projector, DirectLightReadsTheCameraMapping) {
  const std::string checks =
      "<texture type='checkerboard' name='irradiance'><float name='color0' value='0.25'/>"
      "<float name='color1' value='1.5'/></texture>";
  const auto scene = test::scene_from_xml(scene_xml("<integrator type='direct'/>", "", checks, "60"));
  const auto& integrator = dynamic_cast<const PixelIntegrator&>(*scene.integrator);
  const auto estimator = integrator.estimator(*scene, 0);
  const PluginInfo* info = Registry::instance().find("sampler", "independent");
  auto sampler = std::dynamic_pointer_cast<Sampler>(info->create(Properties(*info, {"test", 1})))->clone();
  const double t = std::tan(kPi / 6);
  for (const auto& [x, y] : {std::pair{-0.2f, -0.2f}, {0.2f, -0.2f}, {0.2f, 0.25f}, {-0.3f, 0.4f}, {0.7f, 0.0f}}) {
    float out[3];
    sampler->start_sample(SampleKey::camera({0, 0}), 0, 0);
    estimator->sample({0, 0}, {{x, y, 0.01f}, {0, 0, -1}}, *sampler, out);
    const double u = (1 + x / t) / 2, v = (1 - y / t) / 2;
    const bool in_frame = u > 0 && u < 1 && v > 0 && v < 1;
    const double check = (u < 0.5) == (v < 0.5) ? 0.25 : 1.5;
    EXPECT_NEAR(out[0], in_frame ? kRho * kScale * check : 0, 1e-5) << x << " " << y;
  }
}

// Light paths start through the frame: ptracer and bdpt see the uniformly
// lit plane (a constant image through a 90 degree frame that covers the
// view), region by region at 0.1 % Sidak-corrected, from independent runs.
TEST(Projector, LightPathsAgree) {
  const std::string camera =
      "<sensor type='perspective'><float name='fov' value='90'/><transform name='to_world'>"
      "<lookat origin='0.1, -0.2, 0.6' target='0.1, -0.2, 0' up='0, 1, 0'/></transform>"
      "<film type='hdrfilm'><integer name='width' value='24'/><integer name='height' value='24'/>"
      "<rfilter type='box'/></film></sensor>";
  const auto regions = test::grid_regions(24, 24, 4);
  constexpr int kRuns = 10;
  const double t_critical = test::two_sided_t_critical(test::sidak_alpha(0.001, int(2 * regions.size())), kRuns - 1);
  uint64_t seed = 300;
  for (const auto& [integrator, spp] : {std::pair{"ptracer", 16u}, {"bdpt", 4u}}) {
    const auto scene = test::scene_from_xml(scene_xml(
        "<integrator type='" + std::string(integrator) + "'><integer name='max_depth' value='2'/></integrator>", camera,
        "<rgb name='irradiance' value='0.8'/>", "90"));
    const auto estimates = test::estimate_regions(scene, regions, spp, kRuns, seed += kRuns);
    for (size_t i = 0; i < regions.size(); ++i) {
      const double score = test::difference_score(estimates[i], {kRho * kScale * 0.8, 0, 0});
      EXPECT_LT(std::abs(score), t_critical) << integrator << " region " << i << ": " << estimates[i].mean;
    }
  }
}

// Its power, pi scale A mean(T) with A = 4 tan_x tan_y the frame's area,
// against the flux its light paths carry; the densities they report against
// pdf_Le's.
TEST(Projector, PowerMatchesSampledFlux) {
  const auto scene = test::scene_from_xml(
      "<scene version='3.0.0'><shape type='sphere'/><emitter type='projector'><texture type='checkerboard' "
      "name='irradiance'><float name='color0' value='0.25'/><float name='color1' value='1.5'/></texture>"
      "<float name='fov' value='70'/><float name='scale' value='2'/><transform name='to_world'><rotate x='1' "
      "angle='30'/></transform></emitter></scene>");
  const Emitter& light = *scene->emitters().front();
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0, kOneMinusEpsilon);
  double flux = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const auto le = light.sample_Le({u(rng), u(rng)}, {u(rng), u(rng)});
    if (!le) continue;
    flux += le->Le.r / (le->pdf_pos * le->pdf_dir);
    if (i < 100) {
      float pdf_pos = 0, pdf_dir = 0;
      light.pdf_Le(le->ray, {}, &pdf_pos, &pdf_dir);
      EXPECT_NEAR(pdf_dir, le->pdf_dir, 1e-4 * le->pdf_dir);
    }
  }
  const double t = std::tan(35 * kPi / 180), expected = kPi * 2 * 4 * t * t * (0.25 + 1.5) / 2;
  EXPECT_NEAR(flux / n, expected, 0.01 * expected);
  EXPECT_NEAR(light.power().r, expected, 1e-4 * expected);
}

TEST(Projector, BadParametersNameThemselves) {
  const auto error = [](const std::string& inner) {
    return test::load_error("<scene version='3.0.0'>\n<emitter type='projector'>\n" + inner + "</emitter></scene>",
                            "bad.xml");
  };
  EXPECT_THAT(error(""), HasSubstr("emitter 'projector' requires parameter 'irradiance'"));
  EXPECT_THAT(error("<rgb name='irradiance' value='1'/><float name='scale' value='-1'/>"),
              HasSubstr("bad.xml:3: parameter 'scale' of emitter 'projector': must not be negative"));
  EXPECT_THAT(error("<rgb name='irradiance' value='1'/><float name='fov' value='180'/>"),
              HasSubstr("parameter 'fov' of emitter 'projector': must be between 0 and 180 degrees"));
  EXPECT_THAT(error("<rgb name='irradiance' value='-1'/>"),
              HasSubstr("parameter 'irradiance' of emitter 'projector': must not be negative"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
