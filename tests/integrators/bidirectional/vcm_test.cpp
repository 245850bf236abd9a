// vcm against the stored path references on the Cornell-box family (24x24,
// 16384 spp; scripts/make-test-references.sh): per region of 4x4 pixels,
// the mean over independent runs agrees with the reference by a two-sample
// test at 1%, Sidak-corrected over regions, modes and scenes (Student's t
// with the runs' degrees of freedom). Connections alone are unbiased; the
// merges' bias shrinks with the radius, so the merge-only mode must also
// come closer to the reference from 4 to 64 iterations. Seeds are fixed.

#include <gmock/gmock.h>
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

using testing::HasSubstr;

constexpr int kRes = 24, kRegionsPerSide = 6, kRuns = 16;
const char* const kScenes[] = {"cornell-box",       "cornell-box-glass",    "cornell-box-mirror", "cornell-box-glossy",
                               "cornell-box-phong", "cornell-box-textured", "cornell-box-motion"};
struct Mode {
  const char* integrator;
  uint32_t iterations;
};
const Mode kModes[] = {
    {"vcm", 32}, {"vcm:mode=connect", 32}, {"vcm:mode=merge", 64}, {"vcm:merge_at=after_specular", 32}};
constexpr int kTests = int(std::size(kScenes) * std::size(kModes)) * kRegionsPerSide * kRegionsPerSide;

double mean_abs_difference(const std::vector<test::RegionEstimate>& a, const std::vector<test::RegionEstimate>& b) {
  double sum = 0;
  for (size_t i = 0; i < a.size(); ++i) sum += std::abs(a[i].mean - b[i].mean);
  return sum / double(a.size());
}

class VcmAgreement : public testing::TestWithParam<const char*> {};

TEST_P(VcmAgreement, RegionMeansMatchPath) {
  const std::string name = GetParam();
  const auto regions = test::grid_regions(kRes, kRes, kRegionsPerSide);
  const auto reference = test::reference_regions(name, regions);
  const double t_critical = test::two_sided_t_critical(test::sidak_alpha(0.01, kTests), kRuns - 1);
  for (const Mode& mode : kModes) {
    uint64_t non_finite = 0;
    const auto estimates = test::estimate_regions(test::scene_with_integrator(name, mode.integrator), regions,
                                                  mode.iterations, kRuns, 3000, &non_finite);
    EXPECT_EQ(non_finite, 0u) << name << " " << mode.integrator;
    for (size_t i = 0; i < regions.size(); ++i)
      EXPECT_LT(std::abs(test::difference_score(estimates[i], reference[i])), t_critical)
          << name << " " << mode.integrator << " region (" << regions[i].lo.x << ", " << regions[i].lo.y
          << "): " << estimates[i].mean << " +- " << estimates[i].standard_error << ", reference " << reference[i].mean
          << " +- " << reference[i].standard_error;
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, VcmAgreement, testing::ValuesIn(kScenes), test::scene_test_name);

TEST(Vcm, MergingBiasShrinksWithIterations) {
  const auto regions = test::grid_regions(kRes, kRes, kRegionsPerSide);
  const auto reference = test::reference_regions("cornell-box-glass", regions);
  const auto scene = test::scene_with_integrator("cornell-box-glass", "vcm:mode=merge");
  const auto early = test::estimate_regions(scene, regions, 4, kRuns, 3100);
  const auto late = test::estimate_regions(scene, regions, 64, kRuns, 3200);
  EXPECT_LT(mean_abs_difference(late, reference), mean_abs_difference(early, reference));
}

// Light subpaths draw from (seed, iteration, index) and their splats sum
// exactly, so the thread count changes nothing.
TEST(Vcm, SameImageForAnyThreadCount) {
  const auto scene = test::scene_with_integrator("cornell-box-glass", "vcm");
  const FilmBuffer one = test::render_scene(scene, 3, 11, 1);
  const FilmBuffer two = test::render_scene(scene, 3, 11, 2);
  EXPECT_EQ(one.resolve(), two.resolve());
}

// Merges only after delta lobes: a scene with none has no merge to make,
// and renders as the connections alone, bit for bit; the glass box has
// them.
TEST(Vcm, MergesAfterSpecularOnlyWhereTheSceneHasDeltaLobes) {
  for (const char* name : {"cornell-box", "cornell-box-glass"}) {
    const auto after = test::scene_with_integrator(name, "vcm:merge_at=after_specular");
    const auto connect = test::scene_with_integrator(name, "vcm:mode=connect");
    const bool same = test::render_scene(after, 4, 3, 1).resolve() == test::render_scene(connect, 4, 3, 1).resolve();
    EXPECT_EQ(same, std::string(name) == "cornell-box") << name;
  }
}

TEST(Vcm, BadParameters) {
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><integrator type='vcm'>\n"
                               "<string name='mode' value='all'/></integrator></scene>"),
              HasSubstr("test.xml:2: parameter 'mode' of integrator 'vcm': must be both, connect or merge, not 'all'"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><integrator type='vcm'>\n"
                               "<float name='alpha' value='1'/></integrator></scene>"),
              HasSubstr("test.xml:2: parameter 'alpha' of integrator 'vcm': must be in (0, 1)"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><integrator type='vcm'>\n"
                               "<float name='radius' value='-1'/></integrator></scene>"),
              HasSubstr("test.xml:2: parameter 'radius' of integrator 'vcm': must not be negative"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><integrator type='vcm'>\n"
                               "<string name='mis' value='max'/></integrator></scene>"),
              HasSubstr("test.xml:2: parameter 'mis' of integrator 'vcm': must be power or balance, not 'max'"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><integrator type='vcm'>\n"
                               "<string name='merge_at' value='specular'/></integrator></scene>"),
              HasSubstr("test.xml:2: parameter 'merge_at' of integrator 'vcm': must be every_vertex or after_specular, "
                        "not 'specular'"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><integrator type='vcm'>\n"
                               "<string name='merge_at' value='after_specular'/><string name='mode' value='merge'/>"
                               "</integrator></scene>"),
              HasSubstr("test.xml:2: parameter 'merge_at' of integrator 'vcm': after_specular needs mode both"));
}

// Media and spectral transport are refused with the integrators that
// render them named.
TEST(Vcm, RefusesWhatItDoesNotRenderYet) {
  const auto fog = test::scene_with_integrator("cornell-box-fog", "vcm");
  try {
    fog.integrator->check_scene(*fog.scene);
    FAIL() << "a scene with media was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), HasSubstr("integrator 'vcm' does not render participating media"));
    EXPECT_THAT(e.what(), HasSubstr("bdpt"));
  }
  const auto prism = test::scene_with_integrator("cornell-box-spectral", "vcm");
  try {
    prism.integrator->check_scene(*prism.scene);
    FAIL() << "a spectral scene was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), HasSubstr("integrator 'vcm' does not render with spectral transport"));
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
