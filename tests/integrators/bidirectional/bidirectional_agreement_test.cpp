// ptracer and bdpt against path on the Cornell-box family: per region of
// 4x4 pixels, the mean over its pixels and channels agrees with the stored
// path reference (24x24, 16384 spp; scripts/make-test-references.sh).
//
// ptracer and bdpt splat, so their region means' standard errors come from
// independent runs; the reference's from its per-pixel variance layers
// (taking its channels as fully correlated, an upper bound). Each
// difference is tested at 1%, Sidak-corrected over all regions, integrators
// and scenes, against Student's t with the runs' degrees of freedom (which
// is conservative, the reference's variance being far better known).
//
// A pinhole cannot be reached by a light path through a delta surface, so
// regions where the camera sees a mirror or smooth glass are left out for
// ptracer: it renders nothing there, by design.

#include <gtest/gtest.h>

#include <cmath>

#include "core/image/image_input.h"
#include "core/loader/scene_loader.h"
#include "tests/support/chi2.h"
#include "tests/support/independent_runs.h"
#include "tests/support/test_scenes.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

constexpr int kRes = 24, kRegionsPerSide = 6, kRuns = 32;
const char* const kScenes[] = {"cornell-box",       "cornell-box-glass",    "cornell-box-mirror", "cornell-box-glossy",
                               "cornell-box-phong", "cornell-box-textured", "cornell-box-motion"};
struct Integrator {
  const char* name;
  uint32_t spp;
};
// Many short runs rather than a few long ones: the same cost, but a
// variance estimate with more degrees of freedom and so a tighter bound.
const Integrator kIntegrators[] = {{"ptracer", 64}, {"bdpt", 8}};
constexpr int kTests = int(std::size(kScenes) * std::size(kIntegrators)) * kRegionsPerSide * kRegionsPerSide;

class BidirectionalAgreement : public testing::TestWithParam<const char*> {};

TEST_P(BidirectionalAgreement, RegionMeansMatchPath) {
  const std::string name = GetParam();
  const auto regions = test::grid_regions(kRes, kRes, kRegionsPerSide);
  const auto reference = test::reference_regions(name, regions);
  const double t_critical = test::two_sided_t_critical(test::sidak_alpha(0.01, kTests), kRuns - 1);
  for (const Integrator& integrator : kIntegrators) {
    const auto scene = load_scene(std::string(CAUSTICA_SOURCE_DIR) + "/scenes/" + name + ".xml",
                                  {{"res", std::to_string(kRes)}, {"integrator", integrator.name}});
    uint64_t non_finite = 0;
    const auto estimates = test::estimate_regions(scene, regions, integrator.spp, kRuns, 1000, &non_finite);
    EXPECT_EQ(non_finite, 0u) << name << " " << integrator.name;
    int compared = 0;
    for (size_t i = 0; i < regions.size(); ++i) {
      if (std::string(integrator.name) == "ptracer" && test::seen_through_delta(*scene, regions[i])) continue;
      ++compared;
      const double score = test::difference_score(estimates[i], reference[i]);
      EXPECT_LT(std::abs(score), t_critical)
          << name << " " << integrator.name << " region (" << regions[i].lo.x << ", " << regions[i].lo.y
          << "): " << estimates[i].mean << " +- " << estimates[i].standard_error << ", path reference "
          << reference[i].mean << " +- " << reference[i].standard_error;
    }
    EXPECT_GE(compared, 24) << name << " " << integrator.name;
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, BidirectionalAgreement, testing::ValuesIn(kScenes), test::scene_test_name);

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
