// The thin lens and the orthographic camera seen by every integrator:
// camera rays (path) and light paths joined to the lens (ptracer, bdpt).
//
// A diffuse plane (albedo rho) under a spot light at height 1 shining
// straight down with a hard edge at 30 degrees reflects rho I / (pi d^3) at
// distance d inside the cone and nothing outside. The expected image is
// computed here from the cameras' definitions, not from their code:
// - thin lens at height D above the plane, focused at depth f, lens radius
//   R: the ray through lens point l toward the pinhole ray's point at depth
//   f meets the plane at the pinhole's point plus l (1 - D / f), so the
//   pinhole image is blurred by a disk of radius R |1 - D / f|;
// - orthographic: the film's point straight above.
// Regions of 3x3 pixels (finer than the blur) are compared by independent
// runs at 0.1 %, Sidak-corrected over regions and integrators, Student's t.
// A region the cone's edge barely touches (expected below 0.5 % of the
// brightest region) is lit by too few samples for its mean to be near
// normal; it is only checked to stay that dark. Seeds are fixed.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "tests/support/chi2.h"
#include "tests/support/independent_runs.h"
#include "tests/support/test_scenes.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

constexpr double kRho = 0.6, kIntensity = 2, kCutoffDeg = 30;
constexpr int kPixels = 24;
const Vec2 kCentre{0.1f, -0.2f};  // what the cameras look at, on the plane

double spot_radiance(double x, double y) {
  const double r2 = x * x + y * y, d = std::sqrt(r2 + 1);
  if (std::atan(std::sqrt(r2)) * 180 / M_PI > kCutoffDeg) return 0;
  return kRho * kIntensity / (M_PI * d * d * d);
}

std::string scene_xml(const std::string& integrator, const std::string& sensor) {
  return "<scene version='3.0.0'>" + integrator + sensor +
         "<shape type='rectangle'><transform name='to_world'><scale value='3'/></transform>"
         "<bsdf type='diffuse'><rgb name='reflectance' value='" +
         std::to_string(kRho) + "'/></bsdf></shape><emitter type='spot'><rgb name='intensity' value='" +
         std::to_string(kIntensity) +
         "'/><float name='cutoff_angle' value='30'/><float name='beam_width' value='30'/><transform "
         "name='to_world'><lookat origin='0, 0, 1' target='0, 0, 0' up='0, 1, 0'/></transform></emitter></scene>";
}

std::string film() {
  return "<film type='hdrfilm'><integer name='width' value='24'/><integer name='height' value='24'/>"
         "<rfilter type='box'/></film>";
}

// A camera at `height` above kCentre looking straight down, image up +y.
std::string looking_down(float height) {
  return "<lookat origin='" + std::to_string(kCentre.x) + ", " + std::to_string(kCentre.y) + ", " +
         std::to_string(height) + "' target='" + std::to_string(kCentre.x) + ", " + std::to_string(kCentre.y) +
         ", 0' up='0, 1, 0'/>";
}

// The plane point at fraction (u, v) of a view spanning kCentre +- half
// (image right is +x, image down is -y).
Vec2 view_point(double u, double v, double half) {
  return {float(kCentre.x + half * (2 * u - 1)), float(kCentre.y - half * (2 * v - 1))};
}

// The radiance averaged over pixel (px, py) of a view of half-width `half`,
// blurred by a disk of radius `blur`: midpoint rules over 8x8 points of the
// pixel and 12 rings of 24 points of the disk (equal areas).
double pixel_expectation(int px, int py, double half, double blur) {
  constexpr int n = 8, rings = 12, spokes = 24;
  double sum = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Vec2 p = view_point((px + (i + 0.5) / n) / kPixels, (py + (j + 0.5) / n) / kPixels, half);
      if (blur == 0) {
        sum += spot_radiance(p.x, p.y);
        continue;
      }
      double disk = 0;
      for (int r = 0; r < rings; ++r)
        for (int a = 0; a < spokes; ++a) {
          const double rho = blur * std::sqrt((r + 0.5) / rings), phi = 2 * M_PI * (a + 0.5) / spokes;
          disk += spot_radiance(p.x + rho * std::cos(phi), p.y + rho * std::sin(phi));
        }
      sum += disk / (rings * spokes);
    }
  return sum / (n * n);
}

void expect_regions_match(const std::string& sensor, const std::vector<std::pair<const char*, uint32_t>>& integrators,
                          double half, double blur, uint64_t seed) {
  const auto regions = test::grid_regions(kPixels, kPixels, 8);
  constexpr int kRuns = 10;
  const double t_critical =
      test::two_sided_t_critical(test::sidak_alpha(0.001, int(integrators.size() * regions.size())), kRuns - 1);
  std::vector<double> expected;
  for (const test::Region& g : regions) {
    double sum = 0;
    for (int y = g.lo.y; y < g.hi.y; ++y)
      for (int x = g.lo.x; x < g.hi.x; ++x) sum += pixel_expectation(x, y, half, blur);
    expected.push_back(sum / ((g.hi.x - g.lo.x) * (g.hi.y - g.lo.y)));
  }
  const double brightest = *std::max_element(expected.begin(), expected.end());
  for (const auto& [integrator, spp] : integrators) {
    const auto scene = test::scene_from_xml(scene_xml(integrator, sensor));
    const auto estimates = test::estimate_regions(scene, regions, spp, kRuns, seed += kRuns);
    for (size_t i = 0; i < regions.size(); ++i) {
      if (expected[i] < 0.005 * brightest) {
        EXPECT_LT(estimates[i].mean, 0.02 * brightest) << integrator << " region " << i;
        continue;
      }
      const double score = test::difference_score(estimates[i], {expected[i], 0, 0});
      EXPECT_LT(std::abs(score), t_critical) << integrator << " region " << i << ": " << estimates[i].mean << " +- "
                                             << estimates[i].standard_error << ", expected " << expected[i];
    }
  }
}

const std::vector<std::pair<const char*, uint32_t>> kIntegrators = {
    {"<integrator type='path'><integer name='max_depth' value='2'/></integrator>", 16},
    {"<integrator type='ptracer'><integer name='max_depth' value='2'/></integrator>", 64},
    {"<integrator type='bdpt'><integer name='max_depth' value='2'/></integrator>", 16},
    {"<integrator type='bdpt'><integer name='max_depth' value='2'/><string name='mis' value='balance'/></integrator>",
     16}};

// Height 0.6, fov 90 (the view spans 0.6 each side), focused at 0.3 with a
// lens of radius 0.08: a blur of radius 0.08, 1.6 pixels.
TEST(CameraModels, ThinLensDepthOfFieldAgreesEverywhere) {
  const std::string sensor =
      "<sensor type='thinlens'><float name='fov' value='90'/><float name='aperture_radius' value='0.08'/>"
      "<float name='focus_distance' value='0.3'/><transform name='to_world'>" +
      looking_down(0.6f) + "</transform>" + film() + "</sensor>";
  expect_regions_match(sensor, kIntegrators, 0.6, 0.08 * std::abs(1 - 0.6 / 0.3), 0);
}

// Scaled by 0.5 and 2 above the plane: the view spans 0.5 each side.
TEST(CameraModels, OrthographicAgreesEverywhere) {
  const std::string sensor = "<sensor type='orthographic'><transform name='to_world'><scale x='0.5' y='0.5'/>" +
                             looking_down(2) + "</transform>" + film() + "</sensor>";
  expect_regions_match(sensor, kIntegrators, 0.5, 0, 100);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
