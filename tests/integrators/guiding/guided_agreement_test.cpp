// guided_path against path on the Cornell-box family: per region of 4x4
// pixels, the mean over its pixels and channels agrees with the stored path
// reference (24x24, 16384 spp; scripts/make-test-references.sh), whatever
// the learned distributions are. A pass's samples share the distribution
// the passes before learnt, so the error comes from independent runs (each
// learning afresh), not from per-pixel variances. Each difference is tested
// at 1%, Sidak-corrected over all regions and scenes, against Student's t
// with the runs' degrees of freedom. Guiding is kept on (always_guide)
// where the training passes would judge it does not pay, and wherever a
// guide learnt anything (min_records 0), so that every sample after them
// is guided at every vertex it could be, and meets adjoint-driven
// roulette (the default) wherever its region learnt a radiance.

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

constexpr int kRes = 24, kRegionsPerSide = 6, kRuns = 32;
// 96 samples per pixel: the six training passes (63) and 33 samples by
// what they learnt; fewer leave the glossy box's region means skewed by
// rare bright paths, which a t-test on 32 runs does not allow for.
constexpr uint32_t kSpp = 96;
const char* const kScenes[] = {"cornell-box",       "cornell-box-glass",    "cornell-box-mirror", "cornell-box-glossy",
                               "cornell-box-phong", "cornell-box-textured", "cornell-box-motion"};
constexpr int kTests = int(std::size(kScenes)) * kRegionsPerSide * kRegionsPerSide;

class GuidedAgreement : public testing::TestWithParam<const char*> {};

TEST_P(GuidedAgreement, RegionMeansMatchPath) {
  const std::string name = GetParam();
  const auto regions = test::grid_regions(kRes, kRes, kRegionsPerSide);
  const auto reference = test::reference_regions(name, regions);
  const double t_critical = test::two_sided_t_critical(test::sidak_alpha(0.01, kTests), kRuns - 1);
  auto scene = load_scene(std::string(CAUSTICA_SOURCE_DIR) + "/scenes/" + name + ".xml",
                          {{"res", std::to_string(kRes)}, {"integrator", "guided_path"}});
  scene.integrator = make_integrator("guided_path:always_guide=true,min_records=0", scene.integrator_values);
  uint64_t non_finite = 0;
  const auto estimates = test::estimate_regions(scene, regions, kSpp, kRuns, 2000, &non_finite);
  EXPECT_EQ(non_finite, 0u) << name;
  for (size_t i = 0; i < regions.size(); ++i) {
    const double score = test::difference_score(estimates[i], reference[i]);
    EXPECT_LT(std::abs(score), t_critical)
        << name << " region (" << regions[i].lo.x << ", " << regions[i].lo.y << "): " << estimates[i].mean << " +- "
        << estimates[i].standard_error << ", path reference " << reference[i].mean << " +- "
        << reference[i].standard_error;
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, GuidedAgreement, testing::ValuesIn(kScenes), test::scene_test_name);

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
