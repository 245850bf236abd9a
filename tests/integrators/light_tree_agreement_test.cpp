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
#include "tests/support/test_scenes.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

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

// A room lit by six panels and a disk facing every way (some toward the
// walls, one toward the ceiling), where the tree rules lights out by the
// side they face: the same test at the same significance.
TEST(LightTreeAgreement, FlatLightsFacingEveryWayMatchTheChoiceByPower) {
  std::string lights;
  const char* const turns[] = {"<rotate x='1' angle='90'/>",  "<rotate x='1' angle='-90'/>",
                               "<rotate y='1' angle='90'/>",  "<rotate y='1' angle='-90'/>",
                               "<rotate x='1' angle='180'/>", "<rotate x='1' angle='60'/>"};
  for (int i = 0; i < 6; ++i)
    lights += "<shape type='rectangle'><transform name='to_world'><scale value='0.15'/>" + std::string(turns[i]) +
              "<translate x='" + std::to_string(-1.2 + 0.5 * i) + "' y='" + std::to_string(0.6 + 0.25 * i) + "' z='" +
              std::to_string(0.3 * (i % 3) - 0.3) +
              "'/></transform><emitter type='area'><rgb "
              "name='radiance' value='" +
              std::to_string(2 + 3 * i) + "'/></emitter></shape>";
  lights +=
      "<shape type='disk'><transform name='to_world'><scale value='0.2'/><rotate x='1' angle='90'/>"
      "<translate y='1.9'/></transform><emitter type='area'><rgb name='radiance' value='6'/></emitter></shape>";
  const std::string xml =
      "<scene version='3.0.0'><integrator type='path'/>"
      "<sensor type='perspective'><float name='fov' value='70'/><transform name='to_world'><lookat "
      "origin='0, 1, 3.5' target='0, 1, 0' up='0, 1, 0'/></transform><sampler type='independent'/>"
      "<film type='hdrfilm'><integer name='width' value='16'/><integer name='height' value='16'/></film></sensor>"
      "<shape type='cube'><transform name='to_world'><scale x='2' y='1' z='2'/><translate y='1'/></transform>"
      "<bsdf type='diffuse'><rgb name='reflectance' value='0.6'/></bsdf><boolean name='flip_normals' "
      "value='true'/></shape>" +
      lights + "</scene>";
  const auto room = [&](bool tree) {
    auto scene = test::scene_from_xml(xml);
    SceneFeatures f = scene->features();
    force_light_tree(f, tree);
    scene->set_features(std::move(f));
    return scene;
  };
  const auto regions = test::grid_regions(kRes, kRes, kRegionsPerSide);
  const double t_critical = test::two_sided_t_critical(test::sidak_alpha(0.01, int(regions.size())), kRuns - 1);
  uint64_t non_finite = 0;
  const auto tree = test::estimate_regions(room(true), regions, 128, kRuns, 100, &non_finite);
  const auto power = test::estimate_regions(room(false), regions, 128, kRuns, 500, &non_finite);
  EXPECT_EQ(non_finite, 0u);
  for (size_t i = 0; i < regions.size(); ++i)
    EXPECT_LT(std::abs(test::difference_score(tree[i], power[i])), t_critical)
        << "region (" << regions[i].lo.x << ", " << regions[i].lo.y << "): tree " << tree[i].mean << " +- "
        << tree[i].standard_error << ", power " << power[i].mean << " +- " << power[i].standard_error;
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
