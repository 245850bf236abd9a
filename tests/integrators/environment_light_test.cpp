// A diffuse plane (albedo rho) alone under a uniform sky of radiance Le
// receives irradiance pi Le, so it reflects L = rho Le toward the camera,
// which looks straight down and sees nothing else. Every integrator that
// handles environment light must find it: path and direct through the
// sky's samples and BSDF samples, bdpt through all its strategies (light
// subpaths start on a disk outside the scene), ptracer from the sky alone.
//
// Region means over independent runs, each tested at 0.1% Sidak-corrected
// over regions and integrators against Student's t; seeds are fixed.

#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/chi2.h"
#include "tests/support/independent_runs.h"
#include "tests/support/test_scenes.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

constexpr float kRho = 0.7f, kLe = 0.8f;
constexpr int kRuns = 12;

std::string sky_scene(const std::string& integrator) {
  return "<scene version='3.0.0'>" + integrator +
         "<sensor type='perspective'><float name='fov' value='60'/><transform name='to_world'>"
         "<lookat origin='0, 0, 1.5' target='0, 0, 0' up='0, 1, 0'/></transform><film type='hdrfilm'>"
         "<integer name='width' value='16'/><integer name='height' value='16'/><rfilter type='box'/></film>"
         "</sensor><shape type='rectangle'><bsdf type='diffuse'><rgb name='reflectance' value='" +
         std::to_string(kRho) + "'/></bsdf></shape><emitter type='constant'><rgb name='radiance' value='" +
         std::to_string(kLe) + "'/></emitter></scene>";
}

TEST(EnvironmentLight, DiffusePlaneUnderUniformSky) {
  const std::pair<const char*, uint32_t> integrators[] = {
      {"<integrator type='path'/>", 64},
      {"<integrator type='direct'/>", 64},
      {"<integrator type='bdpt'/>", 64},
      {"<integrator type='bdpt'><string name='mis' value='balance'/></integrator>", 64},
      {"<integrator type='ptracer'/>", 1024}};
  const auto regions = test::grid_regions(16, 16, 4);
  const double t_critical =
      test::two_sided_t_critical(test::sidak_alpha(0.001, int(std::size(integrators) * regions.size())), kRuns - 1);
  const double expected = double(kRho) * kLe;
  uint64_t seed = 0;
  for (const auto& [integrator, spp] : integrators) {
    const auto scene = test::scene_from_xml(sky_scene(integrator));
    uint64_t non_finite = 0;
    const auto estimates = test::estimate_regions(scene, regions, spp, kRuns, seed += kRuns, &non_finite);
    EXPECT_EQ(non_finite, 0u) << integrator;
    for (size_t i = 0; i < regions.size(); ++i)
      EXPECT_LT(std::abs(test::difference_score(estimates[i], {expected, 0, 0})), t_critical)
          << integrator << " region " << i << ": " << estimates[i].mean << " +- " << estimates[i].standard_error
          << ", expected " << expected;
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
