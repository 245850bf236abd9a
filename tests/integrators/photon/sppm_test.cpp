// Stochastic progressive photon mapping against bdpt on the Cornell-box
// family (24x24), the fog and smoke boxes included. Its bias shrinks with the iterations: the mean absolute
// difference of 4x4-pixel region means from bdpt's falls from 4 to 32
// iterations, and at 32 iterations every region agrees with bdpt by a
// two-sample test over independent runs (1%, Sidak-corrected over regions
// and scenes, Student's t). Seeds are fixed.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "core/bsdf/bsdf.h"
#include "core/loader/scene_loader.h"
#include "core/registry/properties.h"
#include "core/sampling/warp.h"
#include "tests/support/chi2.h"
#include "tests/support/independent_runs.h"
#include "tests/support/test_scenes.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using testing::HasSubstr;

constexpr int kRuns = 10;
const char* const kScenes[] = {"cornell-box",     "cornell-box-glass", "cornell-box-mirror", "cornell-box-glossy",
                               "cornell-box-fog", "cornell-box-smoke", "cornell-box-motion"};

double mean_abs_difference(const std::vector<test::RegionEstimate>& a, const std::vector<test::RegionEstimate>& b) {
  double sum = 0;
  for (size_t i = 0; i < a.size(); ++i) sum += std::abs(a[i].mean - b[i].mean);
  return sum / a.size();
}

class SppmAgreement : public testing::TestWithParam<const char*> {};

TEST_P(SppmAgreement, ConvergesToBdpt) {
  const std::string name = GetParam();
  const auto regions = test::grid_regions(24, 24, 6);
  const double t_critical =
      test::two_sided_t_critical(test::sidak_alpha(0.01, int(std::size(kScenes) * regions.size())), kRuns - 1);
  const auto bdpt = test::estimate_regions(test::scene_with_integrator(name, "bdpt"), regions, 32, kRuns, 40);
  const auto sppm = test::scene_with_integrator(name, "sppm:photons=10000");
  uint64_t non_finite = 0;
  const auto early = test::estimate_regions(sppm, regions, 4, kRuns, 50, &non_finite);
  const auto late = test::estimate_regions(sppm, regions, 32, kRuns, 60, &non_finite);
  EXPECT_EQ(non_finite, 0u);
  EXPECT_LT(mean_abs_difference(late, bdpt), mean_abs_difference(early, bdpt)) << name;
  for (size_t i = 0; i < regions.size(); ++i)
    EXPECT_LT(std::abs(test::difference_score(late[i], bdpt[i])), t_critical)
        << name << " region (" << regions[i].lo.x << ", " << regions[i].lo.y << "): sppm " << late[i].mean << " +- "
        << late[i].standard_error << ", bdpt " << bdpt[i].mean << " +- " << bdpt[i].standard_error;
}

INSTANTIATE_TEST_SUITE_P(Scenes, SppmAgreement, testing::ValuesIn(kScenes), test::scene_test_name);

TEST(Sppm, BadParameters) {
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><integrator type='sppm'>\n"
                               "<float name='alpha' value='0'/></integrator></scene>"),
              HasSubstr("test.xml:2: parameter 'alpha' of integrator 'sppm': must be in (0, 1)"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><integrator type='sppm'>\n"
                               "<integer name='photons' value='-5'/></integrator></scene>"),
              HasSubstr("test.xml:2: parameter 'photons' of integrator 'sppm': must be at least 1"));
}

// A material whose every value is NaN, so that sppm's estimate is NaN
// wherever the camera sees it.
class NanBsdf final : public Bsdf {
 public:
  explicit NanBsdf(const Properties&) {}
  uint32_t lobes() const override { return kDiffuseReflection; }
  Color eval(const BsdfContext&, Vec3, Vec3) const override { return Color(std::nanf("")); }
  float pdf(const BsdfContext&, Vec3, Vec3 wi) const override { return cosine_hemisphere_pdf(cos_theta(wi)); }
  std::optional<BsdfSample> sample(const BsdfContext&, Vec3, float, Vec2 u) const override {
    const Vec3 wi = square_to_cosine_hemisphere(u);
    return BsdfSample{wi, Color(std::nanf("")), cosine_hemisphere_pdf(cos_theta(wi)), kDiffuseReflection, 1};
  }
  Color albedo(const BsdfContext&, Vec3) const override { return Color(0.5f); }
};
CAUSTICA_REGISTER_PLUGIN(NanBsdf, "bsdf", "test_nan", {}, {});

// sppm's estimates enter the film through its one entry point, which drops
// and counts what is not finite: the NaN plane leaves finite pixels behind.
TEST(Sppm, NonFiniteEstimatesAreCountedNotWritten) {
  const auto scene = test::scene_from_xml(
      "<scene version='3.0.0'><integrator type='sppm'><integer name='photons' value='500'/></integrator>"
      "<sensor type='perspective'><transform name='to_world'><lookat origin='0, 0, 3' target='0, 0, 0'/></transform>"
      "<film type='hdrfilm'><integer name='width' value='8'/><integer name='height' value='8'/></film></sensor>"
      "<shape type='rectangle'><transform name='to_world'><scale value='10'/></transform>"
      "<bsdf type='test_nan'/></shape>"
      "<emitter type='point'><point name='position' x='0' y='0' z='1'/></emitter></scene>");
  RenderStats stats;
  const FilmBuffer film = test::render_scene(scene, 2, 1, 0, &stats);
  EXPECT_EQ(film.dropped_samples(), 64u);
  EXPECT_EQ(stats.dropped, 64u);
  for (float v : film.resolve()) EXPECT_TRUE(std::isfinite(v));
  EXPECT_THAT(stats.summary, testing::StartsWith("iterations=2, rms radius="));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
