// Hard cases for the estimators that trace light: light behind a glass pane,
// a point light inside a glass sphere, the camera inside glass, and a light
// seen only in a mirror. Every image is finite, and the integrators that
// can render a case agree on it region by region: two-sample tests on
// region means whose standard errors come from independent runs, at 1%
// Sidak-corrected over every comparison, against Student's t. Light tracing
// cannot reach a pinhole through a delta surface, so ptracer is compared
// only where the camera does not look at one; path cannot render light from
// a point through glass (no ray hits the point, no shadow ray passes the
// glass), so it sits out that case.

#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/chi2.h"
#include "tests/support/independent_runs.h"
#include "tests/support/test_scenes.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

constexpr int kRes = 16, kRuns = 24;

std::string scene_xml(const std::string& integrator, const std::string& camera_origin, const std::string& content) {
  return "<scene version='3.0.0'><integrator type='" + integrator +
         "'/><sensor type='perspective'><float name='fov' value='50'/><transform name='to_world'><lookat origin='" +
         camera_origin +
         "' target='0, 0, 0.3' up='0, 0, 1'/></transform><film type='hdrfilm'>"
         "<integer name='width' value='16'/><integer name='height' value='16'/><rfilter type='box'/></film>"
         "</sensor><shape type='rectangle'><transform name='to_world'><scale value='2'/></transform>"
         "<bsdf type='diffuse'><rgb name='reflectance' value='0.6, 0.5, 0.4'/></bsdf></shape>"
         "<shape type='cube'><transform name='to_world'><scale value='0.2'/><translate x='0.5' y='0.3' z='0.2'/>"
         "</transform><bsdf type='diffuse'/></shape>" +
         content + "</scene>";
}

// An area light facing down from height z.
std::string ceiling_light(float z) {
  return "<shape type='rectangle'><transform name='to_world'><scale value='0.3'/><rotate x='1' angle='180'/>"
         "<translate z='" +
         std::to_string(z) + "'/></transform><emitter type='area'><rgb name='radiance' value='8'/></emitter></shape>";
}

struct HardCase {
  const char* name;
  std::string camera_origin;
  std::string content;
  std::vector<const char*> integrators;
};

std::vector<HardCase> hard_cases() {
  const std::string pane =
      "<shape type='cube'><transform name='to_world'><scale x='0.6' y='0.6' z='0.02'/><translate z='1'/>"
      "</transform><bsdf type='dielectric'/></shape>";
  const std::string glass_sphere_with_point_light =
      "<shape type='sphere'><point name='center' x='0' y='0' z='0.6'/><float name='radius' value='0.3'/>"
      "<bsdf type='dielectric'/></shape><emitter type='point'><point name='position' x='0' y='0' z='0.6'/>"
      "<rgb name='intensity' value='3'/></emitter>";
  const std::string glass_around_camera =
      "<shape type='sphere'><point name='center' x='0' y='-2.5' z='0.8'/><float name='radius' value='0.4'/>"
      "<bsdf type='dielectric'/></shape>";
  // The light faces away from the camera, toward a mirror behind it.
  const std::string light_in_mirror =
      "<shape type='rectangle'><transform name='to_world'><scale value='0.25'/><rotate x='1' angle='-90'/>"
      "<translate y='0.6' z='0.9'/></transform><emitter type='area'><rgb name='radiance' value='8'/></emitter>"
      "<bsdf type='diffuse'><rgb name='reflectance' value='0'/></bsdf></shape>"
      "<shape type='rectangle'><transform name='to_world'><scale x='0.8' y='0.6'/><rotate x='1' angle='90'/>"
      "<translate y='1.2' z='0.9'/></transform><bsdf type='conductor'/></shape>";
  return {
      {"light behind a glass pane", "0, -3, 0.6", pane + ceiling_light(1.5), {"path", "bdpt", "ptracer"}},
      {"point light in a glass sphere", "0, -2.5, 1.2", glass_sphere_with_point_light, {"bdpt", "ptracer"}},
      {"camera inside glass", "0, -2.5, 0.8", glass_around_camera + ceiling_light(1.5), {"path", "bdpt"}},
      {"light seen only in a mirror", "0, -2.5, 1.0", light_in_mirror, {"path", "bdpt", "ptracer"}},
  };
}

uint32_t spp_for(const std::string& integrator) { return integrator == "ptracer" ? 64 : 16; }

TEST(LightPathHardCases, FiniteAndAgreeingAcrossIntegrators) {
  const auto regions = test::grid_regions(kRes, kRes, 4);
  const auto cases = hard_cases();
  int comparisons = 0;
  for (const HardCase& c : cases) comparisons += int(c.integrators.size() - 1) * int(regions.size());
  const double t_critical = test::two_sided_t_critical(test::sidak_alpha(0.01, comparisons), kRuns - 1);

  for (const HardCase& c : cases) {
    std::vector<std::vector<test::RegionEstimate>> estimates;
    std::vector<bool> through_delta;
    for (const char* integrator : c.integrators) {
      const auto scene = test::scene_from_xml(scene_xml(integrator, c.camera_origin, c.content));
      uint64_t non_finite = 0;
      estimates.push_back(test::estimate_regions(scene, regions, spp_for(integrator), kRuns, 500, &non_finite));
      EXPECT_EQ(non_finite, 0u) << c.name << ", " << integrator;
      if (through_delta.empty())
        for (const auto& g : regions) through_delta.push_back(test::seen_through_delta(*scene, g));
    }
    // Each integrator against the first; ptracer only where it can see.
    int compared = 0;
    for (size_t i = 1; i < c.integrators.size(); ++i)
      for (size_t r = 0; r < regions.size(); ++r) {
        if (std::string(c.integrators[i]) == "ptracer" && through_delta[r]) continue;
        ++compared;
        const double score = test::difference_score(estimates[i][r], estimates[0][r]);
        EXPECT_LT(std::abs(score), t_critical)
            << c.name << ": " << c.integrators[i] << " " << estimates[i][r].mean << " +- "
            << estimates[i][r].standard_error << " against " << c.integrators[0] << " " << estimates[0][r].mean
            << " +- " << estimates[0][r].standard_error << " in region " << r;
      }
    EXPECT_GE(compared, 8) << c.name;
    // Light reaches the scene at all: the case is not trivially dark.
    double total = 0;
    for (const auto& e : estimates[0]) total += e.mean;
    EXPECT_GT(total, 0.01) << c.name;
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
