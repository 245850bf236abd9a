// The light tree against the choice by power, on the hall of 124 lamps
// (scenes/many-lights.xml) at 16x16: per region of 4x4 pixels, the mean
// over its pixels and channels from 16 independent path renders with each
// selection. Both are unbiased, so they must agree: each difference is
// tested at 1%, Sidak-corrected over the regions, against Student's t with
// the runs' degrees of freedom. A light sample and a BSDF sample that hits
// a lamp meet the same choice probability in their MIS weights only if
// sampling and pmf walk the tree alike; where they do not, the hall's
// lamps and the floor under them shift.

#include <gtest/gtest.h>

#include <cmath>

#include "core/loader/scene_loader.h"
#include "core/scene/scene_features.h"
#include "tests/support/chi2.h"
#include "tests/support/independent_runs.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {

constexpr int kRes = 16, kRegionsPerSide = 4, kRuns = 16;
constexpr uint32_t kSpp = 256;

LoadedScene hall(bool tree) {
  auto scene = load_scene(std::string(CAUSTICA_SOURCE_DIR) + "/scenes/many-lights.xml",
                          {{"res", std::to_string(kRes)}, {"sampler", "independent"}});
  SceneFeatures f = scene->features();
  force_light_tree(f, tree);
  scene->set_features(std::move(f));
  return scene;
}

TEST(LightTreeAgreement, RegionMeansMatchTheChoiceByPower) {
  const auto regions = test::grid_regions(kRes, kRes, kRegionsPerSide);
  const double t_critical = test::two_sided_t_critical(test::sidak_alpha(0.01, int(regions.size())), kRuns - 1);
  uint64_t non_finite = 0;
  const auto tree = test::estimate_regions(hall(true), regions, kSpp, kRuns, 100, &non_finite);
  const auto power = test::estimate_regions(hall(false), regions, kSpp, kRuns, 500, &non_finite);
  EXPECT_EQ(non_finite, 0u);
  for (size_t i = 0; i < regions.size(); ++i) {
    const double score = test::difference_score(tree[i], power[i]);
    EXPECT_LT(std::abs(score), t_critical)
        << "region (" << regions[i].lo.x << ", " << regions[i].lo.y << "): tree " << tree[i].mean << " +- "
        << tree[i].standard_error << ", power " << power[i].mean << " +- " << power[i].standard_error;
  }
}

}  // namespace
}  // namespace caustica
