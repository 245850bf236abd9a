// Radiance through participating media, against closed forms:
//  - a furnace: inside a closed sphere whose inner surface emits Le and
//    reflects with albedo rho, a medium that only scatters (albedo 1)
//    changes nothing: every ray still sees Le / (1 - rho), whatever its
//    extinction, phase function or nesting (media inside null boundaries);
//  - absorption alone: from the centre of a sphere of radius R, a medium
//    that only absorbs leaves Le * exp(-sigma_t R) in each channel; with a
//    ball of it (radius a) at the centre of a sphere that also reflects,
//    the sphere's radiance is Le / (1 - rho A), A = 2 int T(theta) cos
//    sin dtheta being the share of its irradiance that crosses the ball
//    (computed here by quadrature), and the centre sees it times exp(-sigma a).
// Each check is a z-test of the image mean per channel against the value,
// the standard error from the per-pixel sample variances, at 0.1%
// Sidak-corrected over the file's checks; seeds are fixed.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "core/render/direct_light.h"
#include "core/transport/direct_light_in_media.h"
#include "tests/support/samplers.h"
#include "tests/support/test_scenes.h"
#include "tests/support/vol_writer.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using testing::HasSubstr;

constexpr int kChecks = 10 * 3;
const double kZCritical = test::two_sided_z_critical(1 - std::pow(1 - 0.001, 1.0 / kChecks));

std::string medium(const std::string& id, const std::string& sigma_t, const std::string& albedo,
                   const std::string& phase = "<phase type='isotropic'/>") {
  return "<medium type='homogeneous' id='" + id + "'><rgb name='sigma_t' value='" + sigma_t +
         "'/><rgb name='albedo' value='" + albedo + "'/>" + phase + "</medium>";
}

// The camera at the origin inside medium `camera_medium`, the emitting
// sphere of radius 1 around it, and `inside` within it.
std::string sphere_scene(const std::string& integrator, const std::string& media, const std::string& camera_medium,
                         float rho, const std::string& inside = "") {
  return "<scene version='3.0.0'><integrator type='" + integrator + "'/>" + media +
         "<sensor type='perspective'><float name='fov' value='70'/><sampler type='independent'/>"
         "<transform name='to_world'><lookat origin='0, 0, 0' target='1, 0.3, 0.2'/></transform>"
         "<ref id='" +
         camera_medium +
         "'/><film type='hdrfilm'><integer name='width' value='24'/><integer name='height' value='24'/>"
         "<rfilter type='box'/></film></sensor>"
         "<shape type='sphere'><float name='radius' value='1'/><boolean name='flip_normals' value='true'/>"
         "<bsdf type='diffuse'><rgb name='reflectance' value='" +
         std::to_string(rho) + "'/></bsdf><emitter type='area'><rgb name='radiance' value='1'/></emitter></shape>" +
         inside + "</scene>";
}

void expect_radiance(const std::string& xml, Color expected, uint32_t spp, uint64_t seed, const std::string& what) {
  const auto scene = test::scene_from_xml(xml);
  const FilmBuffer film = test::render_scene(scene, spp, seed);
  const auto img = film.resolve();
  const auto var = film.variance();
  const double pixels = double(img.size() / 3);
  for (int c = 0; c < 3; ++c) {
    double sum = 0, var_sum = 0;
    for (size_t i = c; i < img.size(); i += 3) {
      sum += img[i];
      var_sum += var[i];
    }
    const double mean = sum / pixels, standard_error = std::sqrt(var_sum) / pixels;
    // Single-precision rounding where the estimator has no variance.
    const double rounding = 1e-5 * expected[c];
    const double z = (mean - expected[c]) / std::sqrt(standard_error * standard_error + rounding * rounding);
    EXPECT_LT(std::abs(z), kZCritical) << what << ", channel " << c << ": mean " << mean << " +- " << standard_error
                                       << ", expected " << expected[c];
  }
}

TEST(MediumRadiance, ScatteringMediumInAFurnaceChangesNothing) {
  expect_radiance(sphere_scene("path", medium("fog", "1", "1"), "fog", 0.5f), Color(2), 64, 1, "grey, isotropic");
  expect_radiance(
      sphere_scene("volpath", medium("fog", "0.5, 2, 6", "1", "<phase type='hg'><float name='g' value='0.6'/></phase>"),
                   "fog", 0.5f),
      Color(2), 64, 2, "chromatic, forward scattering");
}

TEST(MediumRadiance, HeterogeneousMediumInAFurnaceChangesNothing) {
  // A 4^3 grid of uneven extinction (some voxels empty, channels differing)
  // spread over [-1, 1]^3, around the camera and the whole sphere.
  const auto dir = std::filesystem::temp_directory_path() / "caustica_medium_radiance_test";
  std::filesystem::create_directories(dir);
  std::vector<float> values;
  for (int i = 0; i < 64; ++i)
    for (int c = 0; c < 3; ++c) values.push_back(float((i * 7 + c * 3) % 5) * (c + 1) * 0.6f);
  test::write_vol_file(dir / "uneven.vol", 4, 4, 4, 3, values);
  const std::string smoke =
      "<medium type='heterogeneous' id='smoke'><volume type='gridvolume' name='sigma_t'><string name='filename' "
      "value='" +
      (dir / "uneven.vol").string() +
      "'/><transform name='to_world'><scale value='2'/><translate value='-1, -1, -1'/></transform></volume>"
      "<float name='albedo' value='1'/><integer name='majorant_resolution_factor' value='2'/>"
      "<phase type='hg'><float name='g' value='0.5'/></phase></medium>";
  expect_radiance(sphere_scene("path", smoke, "smoke", 0.5f), Color(2), 64, 7, "heterogeneous");
}

TEST(MediumRadiance, NestedMediaBehindNullBoundariesChangeNothing) {
  // A sphere without a material bounds a second medium inside the first;
  // shadow rays and paths cross it both ways.
  const std::string inner =
      "<shape type='sphere'><point name='center' x='0.3' y='0' z='0'/><float name='radius' value='0.4'/>"
      "<ref name='interior' id='smoke'/><ref name='exterior' id='fog'/></shape>";
  expect_radiance(
      sphere_scene("path",
                   medium("fog", "1", "1") +
                       medium("smoke", "3, 1, 0.2", "1", "<phase type='hg'><float name='g' value='-0.4'/></phase>"),
                   "fog", 0.5f, inner),
      Color(2), 64, 3, "nested");
}

TEST(MediumRadiance, AbsorbingMediumAttenuatesByBeerLambert) {
  expect_radiance(sphere_scene("path", medium("ink", "0.5, 1, 3", "0"), "ink", 0),
                  Color(std::exp(-0.5f), std::exp(-1.0f), std::exp(-3.0f)), 64, 4, "absorbing");
  // The ink fills only a null sphere of radius 0.5 around the camera.
  const std::string ink_ball =
      "<shape type='sphere'><float name='radius' value='0.5'/><ref name='interior' id='ink'/></shape>";
  expect_radiance(sphere_scene("path", medium("ink", "0.5, 1, 3", "0"), "ink", 0, ink_ball),
                  Color(std::exp(-0.25f), std::exp(-0.5f), std::exp(-1.5f)), 64, 5, "absorbing ball");
  // The same ball in glass of index 1: the ray leaves the ink where it is
  // refracted out, not where a null boundary lets it through.
  const std::string glass_ball =
      "<shape type='sphere'><float name='radius' value='0.5'/><bsdf type='dielectric'><float name='int_ior' "
      "value='1'/><float name='ext_ior' value='1'/></bsdf><ref name='interior' id='ink'/></shape>";
  expect_radiance(sphere_scene("path", medium("ink", "0.5, 1, 3", "0"), "ink", 0, glass_ball),
                  Color(std::exp(-0.25f), std::exp(-0.5f), std::exp(-1.5f)), 64, 8, "absorbing glass ball");
}

// A of the comment above, for a ball of radius a and extinction sigma.
double share_through_ball(double a, double sigma) {
  const int n = 100000;
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const double theta = (i + 0.5) * (M_PI / 2) / n;
    const double d = std::sin(theta);  // the ray's distance from the centre
    const double chord = d < a ? 2 * std::sqrt(a * a - d * d) : 0;
    sum += std::exp(-sigma * chord) * std::cos(theta) * std::sin(theta);
  }
  return 2 * sum * (M_PI / 2) / n;
}

TEST(MediumRadiance, ShadowRaysCrossNullBoundariesIntoMedia) {
  const float rho = 0.7f;
  const double sigma[3] = {0.5, 1, 3};
  Color expected;
  for (int c = 0; c < 3; ++c)
    (c == 0   ? expected.r
     : c == 1 ? expected.g
              : expected.b) = float(std::exp(-sigma[c] * 0.5) / (1 - rho * share_through_ball(0.5, sigma[c])));
  const std::string ink_ball =
      "<shape type='sphere'><float name='radius' value='0.5'/><ref name='interior' id='ink'/></shape>";
  expect_radiance(sphere_scene("path", medium("ink", "0.5, 1, 3", "0"), "ink", rho, ink_ball), expected, 64, 6,
                  "reflecting sphere around an absorbing ball");
}

TEST(MediumRadiance, ShadowRaysLeaveATransmittingBoundaryInTheMediumBeyondIt) {
  // From the inside of a rough glass ball of ink toward a light outside in
  // vacuum: the shadow ray crosses no ink, so next-event estimation sees
  // what it would see in a scene without media.
  const auto scene = test::scene_from_xml(
      "<scene version='3.0.0'>" + medium("ink", "2", "0") +
      "<emitter type='point'><point name='position' x='0' y='3' z='0'/><rgb name='intensity' value='5'/></emitter>"
      "<shape type='sphere'><bsdf type='roughdielectric'><float name='alpha' value='0.5'/></bsdf>"
      "<ref name='interior' id='ink'/></shape></scene>");
  const Medium* ink = scene->shapes().front()->interior();
  const auto si = scene->intersect({{0, 0, 0}, normalize(Vec3(0.3f, 1, 0.1f))});
  ASSERT_TRUE(si);
  const SurfaceBsdf bsdf(*si->shape->bsdf(), *si, TransportMode::Radiance);
  const Vec3 wo = normalize(Vec3(-0.3f, -1, -0.1f));
  auto sampler = test::make_sampler("independent");
  const Color in_vacuum = sample_direct_light(*scene, *si, bsdf, wo, 0.5f, {0.5f, 0.5f});
  ASSERT_GT(in_vacuum.g, 0);
  EXPECT_EQ(sample_direct_light_in_media(*scene, *si, bsdf, wo, ink, *sampler, 0.5f, {0.5f, 0.5f}), in_vacuum);
}

TEST(MediumRadiance, IntegratorsWithoutMediaRefuseTheScene) {
  const auto scene = test::scene_from_xml(sphere_scene("direct", medium("fog", "1", "1"), "fog", 0.5f), "fog.xml");
  try {
    test::render_scene(scene, 1);
    FAIL() << "direct rendered a scene with media";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(
        e.what(),
        HasSubstr("integrator 'direct' does not render participating media or null surfaces yet, "
                  "which fog.xml has; render it with aov, bdpt, guided_path, path, photon, ptracer, sppm, volpath"));
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
