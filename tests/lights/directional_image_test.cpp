// A second oracle for the directional light's flux, beside its sampled
// rays crossing the scene (emitter_test.cpp): light tracing draws the
// light's emission over the disk its rays start on, so a diffuse floor lit
// by it alone, seen from above, must show reflectance / pi x irradiance x
// cos(theta) everywhere, region by region over independent runs. Next-event
// estimation of the same light has its closed-form image in
// tests/integrators/analytic_direct_test.cpp.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/math/constants.h"
#include "tests/support/chi2.h"
#include "tests/support/independent_runs.h"
#include "tests/support/test_scenes.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

constexpr double kIrradiance = 2, kReflectance = 0.6, kCosTheta = 0.8;

// The light arrives 36.9 degrees off the floor's normal (direction
// (0.6, 0, -0.8)); the camera sees a square of the floor from above, the
// floor reaching well beyond it so that no light path misses the view for
// want of floor.
TEST(DirectionalImage, LightTracingShowsTheIrradianceTimesTheCosine) {
  const std::string xml =
      "<scene version='3.0.0'><integrator type='ptracer'/><sensor type='perspective'><float name='fov' "
      "value='40'/><transform name='to_world'><lookat origin='0, 0, 4' target='0, 0, 0' up='0, 1, 0'/>"
      "</transform><film type='hdrfilm'><integer name='width' value='32'/><integer name='height' value='32'/>"
      "<rfilter type='box'/></film></sensor><shape type='rectangle'><transform name='to_world'><scale "
      "value='6'/></transform><bsdf type='diffuse'><rgb name='reflectance' value='0.6'/></bsdf></shape>"
      "<emitter type='directional'><vector name='direction' x='0.6' y='0' z='-0.8'/><rgb name='irradiance' "
      "value='2'/></emitter></scene>";
  const auto regions = test::grid_regions(32, 32, 4);
  const auto estimates = test::estimate_regions(test::scene_from_xml(xml), regions, 16, 16, 60);
  const double t_critical = test::two_sided_t_critical(test::sidak_alpha(0.01, int(regions.size())), 15);
  for (size_t k = 0; k < regions.size(); ++k)
    EXPECT_TRUE(
        test::agrees_with_exact(regions[k], estimates[k], kReflectance / kPi * kIrradiance * kCosTheta, t_critical));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
