// Metropolis light transport: its Markov chain in primary sample space
// samples a known target, and the integrator's image and normalisation
// agree with bdpt's on the Cornell-box family (paths of at most five
// segments, mlt's default). Seeds are fixed; every test states its level.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "core/loader/scene_loader.h"
#include "integrators/bidirectional/primary_sample_space.h"
#include "tests/support/chi2.h"
#include "tests/support/independent_runs.h"
#include "tests/support/test_scenes.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using testing::HasSubstr;

// A target over two numbers whose second counts only where the first is
// above one half, so that it is read only there and must catch up lazily
// on the small steps it missed: f(u, v) = g(u) for u <= 1/2 and g(u) h(v)
// beyond, with g(u) = 1 + 3u + 6 [0.3 <= u < 0.4] and h(v) = 2 v + 0.25.
double g(double u) { return 1 + 3 * u + (u >= 0.3 && u < 0.4 ? 6 : 0); }
double h(double v) { return 2 * v + 0.25; }
// Integrals of g and h over [a, b).
double g_integral(double a, double b) {
  const double box = std::max(0.0, std::min(b, 0.4) - std::max(a, 0.3));
  return (b - a) + 1.5 * (b * b - a * a) + 6 * box;
}
double h_integral(double a, double b) { return (b * b - a * a) + 0.25 * (b - a); }

// The chain's state after each step of a Metropolis-Hastings chain in
// primary sample space, with the integrator's acceptance rule. f is at
// least 1/24 of its maximum anywhere and a large step comes with
// probability 0.3, so every step may reach any set of measure m with
// probability at least 0.3 m / 24 (Doeblin's condition): states 1000 steps
// apart are independent, and from the start, to within (1 - 0.0125)^1000 <
// 4e-6 in total variation, a tenth of a count in any bin here.
TEST(PrimarySampleSpace, ChainSamplesItsTarget) {
  constexpr int kBins = 20, kVBins = 10, kSamples = 20000, kThin = 1000;
  PrimarySampleSpace numbers(3, 0, 0.05f);
  const auto target = [&](double* u_out, double* v_out) {
    numbers.start_stream(0);
    const double u = numbers.next_1d();
    *u_out = u;
    if (u <= 0.5) return g(u);
    numbers.start_stream(1);
    *v_out = numbers.next_1d();
    return g(u) * h(*v_out);
  };
  double u = 0, v = 0;
  numbers.mutate(true);
  double f = target(&u, &v);
  numbers.accept();
  std::vector<double> u_counts(kBins), v_counts(kVBins);
  for (int i = 0; i < kSamples; ++i) {
    for (int step = 0; step < kThin; ++step) {
      numbers.mutate(numbers.uniform() < 0.3f);
      double u_new = 0, v_new = 0;
      const double f_new = target(&u_new, &v_new);
      if (numbers.uniform() < std::min(1.0, f_new / f)) {
        numbers.accept();
        f = f_new;
        u = u_new;
        v = v_new;
      } else {
        numbers.reject();
      }
    }
    ++u_counts[std::min(int(u * kBins), kBins - 1)];
    if (u > 0.5) ++v_counts[std::min(int(v * kVBins), kVBins - 1)];
  }
  // Marginal of u: g(u) below one half, g(u) times h's integral (1.25) above.
  const double total = g_integral(0, 0.5) + 1.25 * g_integral(0.5, 1);
  std::vector<double> u_expected(kBins), v_expected(kVBins);
  for (int b = 0; b < kBins; ++b) {
    const double lo = double(b) / kBins, hi = double(b + 1) / kBins;
    u_expected[size_t(b)] = kSamples * g_integral(lo, hi) * (lo >= 0.5 ? 1.25 : 1) / total;
  }
  double above = 0;
  for (double c : v_counts) above += c;
  for (int b = 0; b < kVBins; ++b)
    v_expected[size_t(b)] = above * h_integral(double(b) / kVBins, double(b + 1) / kVBins) / 1.25;
  const double alpha = test::sidak_alpha(0.01, 2);
  const auto u_test = test::chi2_test_counts(u_counts, u_expected);
  const auto v_test = test::chi2_test_counts(v_counts, v_expected);
  EXPECT_GT(u_test.p_value, alpha) << u_test.report;
  EXPECT_GT(v_test.p_value, alpha) << v_test.report;
}

// A rejected step leaves every number as it was, and the streams are apart:
// reading more of one changes no number of another.
TEST(PrimarySampleSpace, RejectionRestoresTheStateAndStreamsAreApart) {
  PrimarySampleSpace numbers(5, 1, 0.01f);
  numbers.mutate(true);
  numbers.start_stream(0);
  const float a = numbers.next_1d(), b = numbers.next_1d();
  numbers.start_stream(1);
  const float c = numbers.next_1d();
  numbers.accept();
  for (const bool large : {false, true}) {
    numbers.mutate(large);
    numbers.start_stream(0);
    EXPECT_NE(numbers.next_1d(), a);
    numbers.start_stream(1);
    for (int i = 0; i < 5; ++i) numbers.next_1d();
    numbers.reject();
    numbers.start_stream(0);
    EXPECT_EQ(numbers.next_1d(), a);
    EXPECT_EQ(numbers.next_1d(), b);
    numbers.start_stream(1);
    EXPECT_EQ(numbers.next_1d(), c);
  }
}

const char* const kMlt = "mlt:bootstrap=5000,chains=64";
constexpr int kRuns = 16;
const char* const kScenes[] = {"cornell-box",       "cornell-box-glass",    "cornell-box-mirror", "cornell-box-glossy",
                               "cornell-box-phong", "cornell-box-textured", "cornell-box-motion"};

// Region means of independent mlt renders (64 passes each) against bdpt's
// at the same depth, by a two-sample test at 1%, Sidak-corrected over
// regions and scenes (Student's t with the runs' degrees of freedom).
class MltAgreement : public testing::TestWithParam<const char*> {};

TEST_P(MltAgreement, RegionMeansMatchBdpt) {
  const std::string name = GetParam();
  const auto regions = test::grid_regions(24, 24, 6);
  const double t_critical =
      test::two_sided_t_critical(test::sidak_alpha(0.01, int(std::size(kScenes) * regions.size())), kRuns - 1);
  const auto bdpt =
      test::estimate_regions(test::scene_with_integrator(name, "bdpt:max_depth=5"), regions, 32, kRuns, 4000);
  uint64_t non_finite = 0;
  const auto mlt =
      test::estimate_regions(test::scene_with_integrator(name, kMlt), regions, 64, kRuns, 4100, &non_finite);
  EXPECT_EQ(non_finite, 0u);
  for (size_t i = 0; i < regions.size(); ++i)
    EXPECT_LT(std::abs(test::difference_score(mlt[i], bdpt[i])), t_critical)
        << name << " region (" << regions[i].lo.x << ", " << regions[i].lo.y << "): mlt " << mlt[i].mean << " +- "
        << mlt[i].standard_error << ", bdpt " << bdpt[i].mean << " +- " << bdpt[i].standard_error;
}

INSTANTIATE_TEST_SUITE_P(Scenes, MltAgreement, testing::ValuesIn(kScenes), test::scene_test_name);

// The bootstrap's normalisation is the image's mean luminance: from
// several seeds, against bdpt's image mean at the same depth (1%, Student's
// t over the seeds, bdpt's error added).
TEST(Mlt, NormalisationIsTheImageMeanLuminance) {
  const auto mlt = test::scene_with_integrator("cornell-box-glass", kMlt);
  const auto bdpt = test::scene_with_integrator("cornell-box-glass", "bdpt:max_depth=5");
  std::vector<double> b, y;
  for (uint64_t seed = 0; seed < uint64_t(kRuns); ++seed) {
    RenderStats stats;
    test::render_scene(mlt, 1, 4200 + seed, 0, &stats);
    const std::string key = "normalisation=";
    b.push_back(std::stod(stats.summary.substr(stats.summary.find(key) + key.size())));
    const auto pixels = test::render_scene(bdpt, 16, 4300 + seed).resolve();
    double sum = 0;
    for (size_t p = 0; p < pixels.size(); p += 3) sum += Color(pixels[p], pixels[p + 1], pixels[p + 2]).luminance();
    y.push_back(sum / double(pixels.size() / 3));
  }
  const auto [b_mean, b_error] = test::mean_and_standard_error(b);
  const auto [y_mean, y_error] = test::mean_and_standard_error(y);
  EXPECT_LT(std::abs(b_mean - y_mean), test::two_sided_t_critical(0.01, kRuns - 1) * std::hypot(b_error, y_error))
      << "normalisation " << b_mean << " +- " << b_error << ", bdpt's mean luminance " << y_mean << " +- " << y_error;
}

// Chains draw from (seed, chain) and their splats sum exactly.
TEST(Mlt, SameImageForAnyThreadCount) {
  const auto scene = test::scene_with_integrator("cornell-box-glass", kMlt);
  EXPECT_EQ(test::render_scene(scene, 3, 9, 1).resolve(), test::render_scene(scene, 3, 9, 2).resolve());
}

TEST(Mlt, BadParameters) {
  const auto error = [](const std::string& param) {
    return test::load_error("<scene version='3.0.0'><integrator type='mlt'>\n" + param + "</integrator></scene>");
  };
  EXPECT_THAT(error("<integer name='max_depth' value='-1'/>"),
              HasSubstr("test.xml:2: parameter 'max_depth' of integrator 'mlt': must be between 1 and 64 (mlt needs a "
                        "finite depth)"));
  EXPECT_THAT(error("<float name='large_step' value='0'/>"),
              HasSubstr("test.xml:2: parameter 'large_step' of integrator 'mlt': must be in (0, 1]"));
  EXPECT_THAT(error("<float name='sigma' value='1'/>"),
              HasSubstr("test.xml:2: parameter 'sigma' of integrator 'mlt': must be in (0, 1)"));
  EXPECT_THAT(error("<integer name='bootstrap' value='0'/>"),
              HasSubstr("test.xml:2: parameter 'bootstrap' of integrator 'mlt': must be at least 1"));
  EXPECT_THAT(error("<integer name='chains' value='0'/>"),
              HasSubstr("test.xml:2: parameter 'chains' of integrator 'mlt': must be at least 1"));
}

TEST(Mlt, RefusesMediaAndSpectralTransport) {
  for (const char* name : {"cornell-box-fog", "cornell-box-spectral"}) {
    const auto scene = test::scene_with_integrator(name, "mlt");
    EXPECT_THROW(scene.integrator->check_scene(*scene.scene), std::invalid_argument) << name;
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
