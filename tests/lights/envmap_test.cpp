// The envmap emitter: sample_Li against pdf_Li (chi-square), sample_Le and
// power against each other, the image's orientation, and a diffuse plane
// under a map whose irradiance is known exactly by quadrature, rendered by
// every integrator that sees environment light; and a map holding a tiny,
// very bright texel (a sun) rendered by path without fireflies.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>

#include "core/math/constants.h"
#include "tests/support/chi2.h"
#include "tests/support/env_map_file.h"
#include "tests/support/independent_runs.h"
#include "tests/support/test_scenes.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

constexpr int kW = 32, kH = 16;

// Radiance of texel (x, y): smooth variation plus a bright patch, so that
// sampling by luminance matters.
Color texel(int x, int y) {
  const float base = 0.2f + 0.1f * float(x % 7) + 0.05f * float(y);
  const bool patch = x >= 20 && x < 23 && y >= 3 && y < 5;
  return Color(base, base * 0.8f, base * 0.6f) + (patch ? Color(30, 25, 20) : Color());
}

fs::path write_map(const std::string& name, Color (*value)(int, int), int w = kW, int h = kH) {
  return test::write_env_map(name, value, w, h);
}

std::string envmap(const fs::path& file, const std::string& extra = "") {
  return "<emitter type='envmap'><string name='filename' value='" + file.string() + "'/>" + extra + "</emitter>";
}

TEST(Envmap, SampledDirectionsFollowPdfLi) {
  const auto scene =
      test::scene_from_xml("<scene version='3.0.0'>" +
                           envmap(write_map("caustica_env.exr", texel),
                                  "<transform name='to_world'><rotate x='1' y='1' angle='40'/></transform>") +
                           "</scene>");
  const Emitter& light = *scene->emitters().front();
  const ReferencePoint ref{{0, 0, 0}, {}, {}};
  const auto result = test::chi2_test_sphere(
      [&](test::UniformSource& u) -> std::optional<Vec3> {
        const auto ls = light.sample_Li(ref, u.next_2d());
        if (!ls) return std::nullopt;
        return ls->wi;
      },
      [&](const Vec3& w) { return double(light.pdf_Li(ref, w, {})); });
  EXPECT_GT(result.p_value, 0.001) << result.report;
  EXPECT_NEAR(test::integrate_sphere([&](const Vec3& w) { return double(light.pdf_Li(ref, w, {})); }), 1, 2e-3);
  // Each sample's radiance is what a ray in its direction sees.
  test::UniformSource u(3);
  for (int i = 0; i < 100; ++i) {
    const auto ls = light.sample_Li(ref, u.next_2d());
    ASSERT_TRUE(ls);
    EXPECT_EQ(ls->Li.r, light.Le_infinite(ls->wi, 0).r);
  }
}

TEST(Envmap, PowerMatchesSampledFlux) {
  const auto scene = test::scene_from_xml("<scene version='3.0.0'><shape type='sphere'/>" +
                                          envmap(write_map("caustica_env.exr", texel)) + "</scene>");
  const Emitter& light = *scene->emitters().front();
  std::mt19937 rng(4);
  std::uniform_real_distribution<float> u(0, kOneMinusEpsilon);
  double flux = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const auto le = light.sample_Le({u(rng), u(rng)}, {u(rng), u(rng)});
    ASSERT_TRUE(le);
    float pdf_pos = 0, pdf_dir = 0;
    light.pdf_Le(le->ray, {}, &pdf_pos, &pdf_dir);
    EXPECT_NEAR(pdf_dir / le->pdf_dir, 1, 1e-3);
    flux += le->Le.r / (le->pdf_pos * le->pdf_dir);
  }
  EXPECT_NEAR(flux / n, light.power().r, 0.02 * light.power().r);
}

// Mitsuba's orientation: the top row looks along +y, the left edge along
// -z, the centre column along +z, and a quarter of the way along +x.
TEST(Envmap, ImageOrientationIsMitsubas) {
  const auto marker = [](int x, int y) {
    if (y == 0) return Color(1, 0, 0);
    if (y == kH - 1) return Color(0, 1, 0);
    if (y == kH / 2 && x == kW / 2) return Color(0, 0, 1);
    if (y == kH / 2 && x == kW / 4) return Color(1, 1, 0);
    return Color(0.1f);
  };
  const auto scene =
      test::scene_from_xml("<scene version='3.0.0'>" + envmap(write_map("caustica_marker.exr", marker)) + "</scene>");
  const Emitter& light = *scene->emitters().front();
  EXPECT_EQ(light.Le_infinite({0, 1, 0}, 0).r, 1);
  EXPECT_EQ(light.Le_infinite({0, -1, 0}, 0).g, 1);
  EXPECT_EQ(light.Le_infinite(normalize(Vec3(-0.01f, -0.01f, 1)), 0).b, 1);
  EXPECT_EQ(light.Le_infinite(normalize(Vec3(1, -0.01f, 0.01f)), 0).r, 1);
  EXPECT_EQ(light.Le_infinite(normalize(Vec3(1, -0.01f, 0.01f)), 0).g, 1);
}

// A diffuse plane facing +y under the map receives the irradiance
// E = sum over texels above the horizon of L dphi (sin^2 theta1 - sin^2
// theta0) / 2, exact for texels bounded by lines of latitude; it reflects
// rho E / pi. Region means of independent runs against it (Student's t, 1%
// Sidak-corrected over regions and integrators).
TEST(Envmap, DiffusePlaneReflectsTheIrradianceForEveryIntegrator) {
  const fs::path map = write_map("caustica_env.exr", texel);
  double irradiance[3] = {0, 0, 0};
  for (int y = 0; y < kH / 2; ++y) {
    const double t0 = M_PI * y / kH, t1 = M_PI * (y + 1) / kH;
    const double weight = (2 * M_PI / kW) * (std::sin(t1) * std::sin(t1) - std::sin(t0) * std::sin(t0)) / 2;
    for (int x = 0; x < kW; ++x) {
      const Color c = texel(x, y);
      irradiance[0] += c.r * weight;
      irradiance[1] += c.g * weight;
      irradiance[2] += c.b * weight;
    }
  }
  constexpr double kRho = 0.5;
  const double expected = kRho / M_PI * (irradiance[0] + irradiance[1] + irradiance[2]) / 3;
  const std::pair<const char*, uint32_t> integrators[] = {{"path", 16}, {"direct", 16}, {"ptracer", 64},
                                                          {"bdpt", 16}, {"photon", 1},  {"sppm", 1}};
  const auto regions = test::grid_regions(16, 16, 4);
  constexpr int kRuns = 12;
  const double t_critical =
      test::two_sided_t_critical(test::sidak_alpha(0.01, int(std::size(integrators) * regions.size())), kRuns - 1);
  uint64_t seed = 0;
  for (const auto& [name, spp] : integrators) {
    const auto scene = test::scene_from_xml(
        std::string("<scene version='3.0.0'><integrator type='") + name +
        "'/><sensor type='perspective'><float name='fov' value='30'/><transform name='to_world'>"
        "<lookat origin='0, 4, 0' target='0, 0, 0' up='0, 0, 1'/></transform><film type='hdrfilm'>"
        "<integer name='width' value='16'/><integer name='height' value='16'/><rfilter type='box'/></film>"
        "</sensor><shape type='rectangle'><transform name='to_world'><scale value='3'/><rotate x='1' "
        "angle='-90'/></transform><bsdf type='diffuse'><rgb name='reflectance' value='0.5'/></bsdf></shape>" +
        envmap(map) + "</scene>");
    const auto estimates = test::estimate_regions(scene, regions, spp, kRuns, seed += kRuns);
    for (size_t i = 0; i < regions.size(); ++i)
      EXPECT_LT(std::abs(test::difference_score(estimates[i], {expected, 0, 0})), t_critical)
          << name << " region " << i << ": " << estimates[i].mean << " +- " << estimates[i].standard_error
          << ", expected " << expected;
  }
}

// One texel of radiance 1e5 (a sun of 1e-3 sr) over a dim sky: sampled by
// luminance, the sun's light reaches every pixel of the plane with little
// noise; BSDF-sampled hits of it are weighed down by MIS.
TEST(Envmap, ASunRendersWithoutFireflies) {
  const auto sun = [](int x, int y) { return x == 40 && y == 10 ? Color(1e5f) : Color(0.1f); };
  const auto scene = test::scene_from_xml(
      "<scene version='3.0.0'><integrator type='path'/><sensor type='perspective'><float name='fov' value='30'/>"
      "<transform name='to_world'><lookat origin='0, 4, 0' target='0, 0, 0' up='0, 0, 1'/></transform>"
      "<film type='hdrfilm'><integer name='width' value='16'/><integer name='height' value='16'/>"
      "<rfilter type='box'/></film></sensor><shape type='rectangle'><transform name='to_world'><scale "
      "value='3'/><rotate x='1' angle='-90'/></transform><bsdf type='diffuse'/></shape>" +
      envmap(write_map("caustica_sun.exr", sun, 128, 64)) + "</scene>");
  const auto image = test::render_scene(scene, 16, 5).resolve();
  double sum = 0, largest = 0;
  for (size_t p = 0; p < image.size() / 3; ++p) {
    sum += image[p * 3];
    largest = std::max(largest, double(image[p * 3]));
  }
  const double mean = sum / double(image.size() / 3);
  EXPECT_GT(mean, 1);  // the sun dominates
  EXPECT_LT(largest, 1.3 * mean);
}

TEST(Envmap, BadMapsAreRefused) {
  const fs::path negative =
      write_map("caustica_negative.exr", [](int x, int y) { return x == 3 && y == 2 ? Color(-1) : Color(1); });
  EXPECT_THAT(test::load_error("<scene version='3.0.0'>" + envmap(negative) + "</scene>"),
              HasSubstr("has a negative or non-finite value at pixel (3, 2)"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'>" + envmap("/nowhere/sky.exr") + "</scene>"),
              HasSubstr("parameter 'filename' of emitter 'envmap'"));
}

// Values near float's limit: a finite 3e38 texel is no error in the file
// (its channels' sum would overflow, not its channels), but around a ball
// of radius 10 the map's power (radiance times the solid angle, times the
// disk its light enters through) overflows; a scale that takes a texel
// past float's range is named with the texel.
TEST(Envmap, RadianceBeyondFloatIsRefusedByWhatOverflows) {
  const fs::path huge =
      write_map("caustica_huge.exr", [](int x, int y) { return x == 5 && y == 3 ? Color(3e38f) : Color(1); });
  EXPECT_NO_THROW(test::scene_from_xml("<scene version='3.0.0'>" + envmap(huge) + "</scene>"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'>\n" + envmap(huge) +
                               "<shape type='sphere'><float name='radius' value='10'/></shape></scene>"),
              HasSubstr("test.xml:2: the emitter's power (inf, inf, inf W) overflows single precision; express the "
                        "scene in other units"));
  EXPECT_THAT(
      test::load_error("<scene version='3.0.0'>" +
                       envmap(write_map("caustica_env.exr", texel), "<float name='scale' value='1e38'/>") + "</scene>"),
      HasSubstr("parameter 'scale' of emitter 'envmap': '" + (fs::temp_directory_path() / "caustica_env.exr").string() +
                "' times 1e+38 overflows single precision at pixel (20, 3) (its value there is 30.95); "
                "express the scene in other units"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
