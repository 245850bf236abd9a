// Phase functions: sampling against the density (chi-square, Sidak-corrected
// to 0.1% over the file's tests), normalisation and mean cosine by
// quadrature of eval() (an integral computed apart from the sampler),
// reciprocity, the direction convention, and bad parameters.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "core/math/constants.h"
#include "core/math/frame.h"
#include "tests/support/chi2.h"
#include "tests/support/media.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using testing::HasSubstr;

const float kGs[] = {-0.9f, -0.5f, 0.0f, 0.0005f, 0.3f, 0.9f};
// One chi-square test per g and the isotropic function.
const double kAlpha = 1 - std::pow(1 - 0.001, 1.0 / (std::size(kGs) + 1));

std::shared_ptr<const Medium> medium_with_phase(const std::string& phase) {
  return test::make_medium("<medium type='homogeneous'>" + phase + "</medium>");
}

std::shared_ptr<const Medium> hg(float g) {
  return medium_with_phase("<phase type='hg'><float name='g' value='" + std::to_string(g) + "'/></phase>");
}

const Vec3 kWo = normalize(Vec3(0.3f, -0.5f, 0.8f));

// The integral of p(wo, wi) * h(mu) over the sphere of wi, mu being the
// cosine of the scattering angle (-wo . wi), by the midpoint rule in mu
// (p depends on mu alone, so the azimuth integrates to 2 pi exactly) with
// directions built around wo.
double integrate_over_mu(const PhaseFunction& phase, double (*h)(double)) {
  const int n = 200000;
  const Frame frame = Frame::from_normal(kWo);
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const double mu = -1 + (i + 0.5) * 2.0 / n;
    const double s = std::sqrt(std::max(0.0, 1 - mu * mu));
    const Vec3 wi = -frame.to_world({float(s * std::cos(1.0)), float(s * std::sin(1.0)), float(mu)});
    sum += phase.eval(kWo, wi) * h(mu);
  }
  return sum * 2 * kPi * 2.0 / n;
}

TEST(PhaseFunction, SamplesFollowTheDensity) {
  std::vector<std::pair<std::string, std::shared_ptr<const Medium>>> cases = {
      {"isotropic", medium_with_phase("<phase type='isotropic'/>")}};
  for (float g : kGs) cases.emplace_back("hg g=" + std::to_string(g), hg(g));
  for (const auto& [name, medium] : cases) {
    const PhaseFunction& phase = medium->phase();
    const auto chi2 = test::chi2_test_sphere(
        [&](test::UniformSource& u) -> std::optional<Vec3> {
          const auto s = phase.sample(kWo, u.next_2d());
          if (!s) return std::nullopt;
          EXPECT_NEAR(s->pdf, phase.eval(kWo, s->wi), 1e-4f * s->pdf);
          return s->wi;
        },
        [&](const Vec3& wi) { return double(phase.eval(kWo, wi)); }, {.sample_count = 400000});
    EXPECT_GT(chi2.p_value, kAlpha) << name << "\n" << chi2.report;
  }
}

TEST(PhaseFunction, IntegratesToOneWithMeanCosineG) {
  for (float g : kGs) {
    const auto medium = hg(g);
    EXPECT_NEAR(integrate_over_mu(medium->phase(), [](double) { return 1.0; }), 1.0, 1e-4) << g;
    EXPECT_NEAR(integrate_over_mu(medium->phase(), [](double mu) { return mu; }), g, 1e-4) << g;
    EXPECT_EQ(medium->phase().mean_cosine(), g);
  }
  const auto iso = medium_with_phase("<phase type='isotropic'/>");
  EXPECT_NEAR(integrate_over_mu(iso->phase(), [](double) { return 1.0; }), 1.0, 1e-6);
  EXPECT_FLOAT_EQ(iso->phase().eval(kWo, kWo), 1 / (4 * kPi));
}

TEST(PhaseFunction, HgMatchesItsFormulaAndIsReciprocal) {
  const auto medium = hg(0.6f);
  const Vec3 wi = normalize(Vec3(-0.2f, 0.7f, 0.1f));
  // The light arrives along -wi and leaves along wo.
  const double mu = -dot(kWo, wi), g = 0.6;
  const double expected = (1 - g * g) / (4 * M_PI * std::pow(1 + g * g - 2 * g * mu, 1.5));
  EXPECT_NEAR(medium->phase().eval(kWo, wi), expected, 1e-6 * expected);
  EXPECT_EQ(medium->phase().eval(kWo, wi), medium->phase().eval(wi, kWo));
}

TEST(PhaseFunction, ForwardScatteringContinuesThePath) {
  // A camera path arriving along -wo continues along -wo when g > 0.
  const auto forward = hg(0.9f), backward = hg(-0.9f);
  test::UniformSource u(3);
  double forward_sum = 0, backward_sum = 0;
  const int n = 10000;
  for (int i = 0; i < n; ++i) {
    const Vec2 s = u.next_2d();
    forward_sum += dot(forward->phase().sample(kWo, s)->wi, -kWo);
    backward_sum += dot(backward->phase().sample(kWo, s)->wi, -kWo);
  }
  // The mean cosine is g; its standard error is below 0.01 here.
  EXPECT_NEAR(forward_sum / n, 0.9, 0.03);
  EXPECT_NEAR(backward_sum / n, -0.9, 0.03);
}

TEST(PhaseFunction, BadParametersAreErrors) {
  for (const char* g : {"1", "-1", "1.5"})
    EXPECT_THAT(test::load_error(std::string("<scene version='3.0.0'>\n<medium type='homogeneous' id='m'>\n<phase "
                                             "type='hg'>\n<float name='g' value='") +
                                     g + "'/></phase></medium></scene>",
                                 "bad.xml"),
                HasSubstr("bad.xml:4: parameter 'g' of phase 'hg': must lie strictly between -1 and 1"))
        << g;
  EXPECT_THAT(test::load_error("<scene version='3.0.0'>\n<medium type='homogeneous' id='m'>\n<phase type='rayleigh'/>"
                               "</medium></scene>",
                               "bad.xml"),
              HasSubstr("bad.xml:3: unknown phase type 'rayleigh' (available: hg, isotropic)"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
