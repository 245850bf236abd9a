// The photon integrator through participating media: on the glass Cornell
// box in fog (24x24), every region, the caustic under the sphere included,
// agrees with path: caustic photons cross the fog unscattered or stop, and
// the path tracer counts exactly the paths the photons leave (those that
// scatter in the fog). Region means over independent runs, each difference
// at 1% Sidak-corrected against Student's t; seeds fixed.

#include <gtest/gtest.h>

#include <cmath>

#include "core/loader/scene_loader.h"
#include "tests/support/chi2.h"
#include "tests/support/independent_runs.h"
#include "tests/support/test_scenes.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

constexpr int kRuns = 8;

LoadedScene glass_fog_box(const std::string& integrator) {
  auto scene = load_scene(std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box-glass-fog.xml", {{"res", "24"}});
  scene.integrator = make_integrator(integrator);
  return scene;
}

TEST(PhotonInMedia, AgreesWithPathRegionByRegion) {
  std::vector<test::Region> regions = test::grid_regions(24, 24, 6);
  regions.push_back({{13, 20}, {18, 23}});  // the caustic under the sphere
  const double t_critical = test::two_sided_t_critical(test::sidak_alpha(0.01, int(regions.size())), kRuns - 1);
  const auto photon = glass_fog_box("photon:photons=20000");
  ASSERT_TRUE(photon->features().caustic_paths);
  uint64_t non_finite = 0;
  const auto ph = test::estimate_regions(photon, regions, 32, kRuns, 100, &non_finite);
  EXPECT_EQ(non_finite, 0u);
  const auto path = test::estimate_regions(glass_fog_box("path"), regions, 256, kRuns, 300);
  for (size_t i = 0; i < regions.size(); ++i)
    EXPECT_LT(std::abs(test::difference_score(ph[i], path[i])), t_critical)
        << "region (" << regions[i].lo.x << ", " << regions[i].lo.y << "): photon " << ph[i].mean << " +- "
        << ph[i].standard_error << ", path " << path[i].mean << " +- " << path[i].standard_error;
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
