// Inside a closed sphere whose inner surface emits Le and reflects diffusely
// with albedo rho, every ray sees L = Le * sum_k rho^k: Le / (1 - rho) with
// unlimited depth, the partial sum when max_depth cuts the series.
//
// Each case is a z-test of the image mean against that value, with the
// standard error estimated from the per-pixel sample variances, at
// significance 0.1% each (two-sided). Light tracing and BDPT splat, so their
// standard error comes from independent runs instead, and the critical value
// from Student's t, Sidak-corrected over their cases at 0.1%. Seeds are
// fixed, so the outcome is deterministic.

#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/chi2.h"
#include "tests/support/image_mean.h"
#include "tests/support/independent_runs.h"
#include "tests/support/test_scenes.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

const double kZCritical = test::two_sided_z_critical(0.001);

std::string sphere_scene(const std::string& integrator, float Le, float rho,
                         const std::string& sampler = "independent") {
  return "<scene version='3.0.0'>" + integrator +
         "<sensor type='perspective'><float name='fov' value='70'/><sampler type='" + sampler +
         "'/>"
         "<transform name='to_world'><lookat origin='0.1, 0.2, 0' target='1, 0.3, 0.2'/></transform>"
         "<film type='hdrfilm'><integer name='width' value='24'/><integer name='height' value='24'/>"
         "<rfilter type='box'/></film></sensor>"
         "<shape type='sphere'><float name='radius' value='1'/><boolean name='flip_normals' value='true'/>"
         "<bsdf type='diffuse'><rgb name='reflectance' value='" +
         std::to_string(rho) + "'/></bsdf><emitter type='area'><rgb name='radiance' value='" + std::to_string(Le) +
         "'/></emitter></shape></scene>";
}

struct MeanEstimate {
  double mean = 0, standard_error = 0;
};

// Mean of every channel of every pixel, and its standard error. The
// channels of a pixel are correlated (in a grey scene, identical), so the
// error of their mean is bounded by the mean of their errors.
MeanEstimate image_mean(const FilmBuffer& film) {
  const test::ImageMean m = test::image_mean(film);
  return {(m.mean[0] + m.mean[1] + m.mean[2]) / 3,
          (m.standard_error[0] + m.standard_error[1] + m.standard_error[2]) / 3};
}

void expect_radiance(const std::string& integrator, double expected, uint32_t spp, uint64_t seed) {
  const auto scene = test::scene_from_xml(sphere_scene(integrator, 1.0f, 0.5f));
  const MeanEstimate m = image_mean(test::render_scene(scene, spp, seed));
  // Where the estimator has (almost) no variance, single-precision rounding
  // dominates the error; it is allowed for as a relative 1e-5 spread.
  const double rounding = 1e-5 * expected;
  const double z = (m.mean - expected) / std::sqrt(m.standard_error * m.standard_error + rounding * rounding);
  EXPECT_LT(std::abs(z), kZCritical) << integrator << ": mean " << m.mean << " +- " << m.standard_error << ", expected "
                                     << expected;
}

TEST(ClosedSphere, PathWithRussianRouletteIsUnbiased) {
  expect_radiance("<integrator type='path'><integer name='rr_depth' value='1'/></integrator>", 2.0, 64, 1);
}

// Roulette at any throughput from the first bounce (Mitsuba's rule), and
// only below a threshold the walls' albedo reaches after one bounce.
TEST(ClosedSphere, PathWithRouletteAtAnyThroughputIsUnbiased) {
  expect_radiance(
      "<integrator type='path'><integer name='rr_depth' value='1'/>"
      "<float name='rr_threshold' value='1e30'/></integrator>",
      2.0, 64, 7);
  expect_radiance(
      "<integrator type='path'><integer name='rr_depth' value='1'/>"
      "<float name='rr_threshold' value='0.6'/></integrator>",
      2.0, 64, 8);
}

TEST(ClosedSphere, PathWithDefaultRouletteIsUnbiased) { expect_radiance("<integrator type='path'/>", 2.0, 64, 2); }

TEST(ClosedSphere, PathWithoutRouletteMatchesTheTruncatedSeries) {
  // rr_depth beyond max_depth: no path ever meets Russian roulette.
  const int depth = 12;
  const double expected = (1 - std::pow(0.5, depth)) / (1 - 0.5);
  expect_radiance(
      "<integrator type='path'><integer name='max_depth' value='12'/>"
      "<integer name='rr_depth' value='100'/></integrator>",
      expected, 32, 3);
}

TEST(ClosedSphere, MaxDepthOneSeesOnlyEmission) {
  const auto scene = test::scene_from_xml(
      sphere_scene("<integrator type='path'><integer name='max_depth' value='1'/></integrator>", 1.0f, 0.5f));
  for (float v : test::render_scene(scene, 2).resolve()) EXPECT_FLOAT_EQ(v, 1.0f);
}

TEST(ClosedSphere, DirectSeesOneBounce) {
  expect_radiance("<integrator type='direct'/>", 1.5, 32, 4);
  expect_radiance("<integrator type='path'><integer name='max_depth' value='2'/></integrator>", 1.5, 32, 5);
}

// Radiance rises fast with albedo near 1, where Russian roulette matters most.
TEST(ClosedSphere, HighAlbedoStaysUnbiased) {
  const auto scene = test::scene_from_xml(sphere_scene("<integrator type='path'/>", 0.5f, 0.9f));
  const MeanEstimate m = image_mean(test::render_scene(scene, 64, 6));
  EXPECT_LT(std::abs(m.mean - 5.0) / m.standard_error, kZCritical) << m.mean << " +- " << m.standard_error;
}

// The furnace crossed with the stratifying samplers: every integrator
// stays unbiased. Independent runs give the standard errors (a stratified
// pixel's sample spread overstates its error).
TEST(ClosedSphere, EveryIntegratorIsUnbiasedWithStratifyingSamplers) {
  const std::pair<const char*, double> cases[] = {{"<integrator type='path'/>", 2.0},
                                                  {"<integrator type='direct'/>", 1.5},
                                                  {"<integrator type='ptracer'/>", 2.0},
                                                  {"<integrator type='bdpt'/>", 2.0}};
  constexpr int kRuns = 12;
  const char* const samplers[] = {"ldsampler", "stratified", "multijitter", "halton"};
  const double t_critical =
      test::two_sided_t_critical(test::sidak_alpha(0.001, int(std::size(cases) * std::size(samplers))), kRuns - 1);
  uint64_t seed = 300;
  for (const char* sampler : samplers)
    for (const auto& [integrator, expected] : cases) {
      const auto scene = test::scene_from_xml(sphere_scene(integrator, 1.0f, 0.5f, sampler));
      const auto region = test::estimate_regions(scene, {{{0, 0}, {24, 24}}}, 16, kRuns, seed += kRuns)[0];
      const double rounding = 1e-5 * expected;
      EXPECT_LT(std::abs(region.mean - expected), t_critical * std::hypot(region.standard_error, rounding))
          << sampler << ", " << integrator << ": " << region.mean << " +- " << region.standard_error << ", expected "
          << expected;
    }
}

TEST(ClosedSphere, LightTracingAndBidirectionalAreUnbiased) {
  struct Case {
    const char* integrator;
    double expected;
    uint32_t spp;  // a light path per sample makes ptracer's estimate noisier
  };
  const double truncated = 1 + 0.5 + 0.25;  // max_depth 3
  const Case cases[] = {
      {"<integrator type='ptracer'/>", 2.0, 32},
      {"<integrator type='ptracer'><integer name='rr_depth' value='1'/></integrator>", 2.0, 32},
      {"<integrator type='ptracer'><integer name='max_depth' value='3'/></integrator>", truncated, 32},
      {"<integrator type='bdpt'/>", 2.0, 4},
      {"<integrator type='bdpt'><integer name='rr_depth' value='1'/></integrator>", 2.0, 4},
      {"<integrator type='bdpt'><string name='mis' value='balance'/></integrator>", 2.0, 4},
      {"<integrator type='bdpt'><integer name='max_depth' value='3'/></integrator>", truncated, 4},
  };
  constexpr int kRuns = 12;
  const double t_critical = test::two_sided_t_critical(test::sidak_alpha(0.001, int(std::size(cases))), kRuns - 1);
  uint64_t seed = 100;
  for (const Case& c : cases) {
    const auto scene = test::scene_from_xml(sphere_scene(c.integrator, 1.0f, 0.5f));
    const auto region = test::estimate_regions(scene, {{{0, 0}, {24, 24}}}, c.spp, kRuns, seed += kRuns)[0];
    const double score = test::difference_score(region, {c.expected, 0, 0});
    EXPECT_LT(std::abs(score), t_critical)
        << c.integrator << ": mean " << region.mean << " +- " << region.standard_error << ", expected " << c.expected;
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
