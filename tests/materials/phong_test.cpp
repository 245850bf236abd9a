#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/math/constants.h"
#include "tests/support/bsdf_checks.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using test::direction;
using ::testing::HasSubstr;

const float kThetas[] = {0.0f, 0.7f, 1.4f, 1.5607f};  // down to 0.01 rad from grazing
const float kExponents[] = {1.0f, 30.0f, 1000.0f};

// Chi-square tests in this file: 3 exponents x 4 incident angles (counted in kMaterialChi2Tests).
const double kAlpha = test::material_chi2_alpha();

std::shared_ptr<Bsdf> phong(const std::string& kd, const std::string& ks, float exponent) {
  return test::make_bsdf("<bsdf type='phong'><rgb name='diffuse_reflectance' value='" + kd +
                         "'/><rgb name='specular_reflectance' value='" + ks + "'/><float name='exponent' value='" +
                         std::to_string(exponent) + "'/></bsdf>");
}

TEST(PhongBsdf, SamplesFollowThePdf) {
  for (float exponent : kExponents) {
    const auto bsdf = phong("0.2, 0.3, 0.1", "0.4, 0.5, 0.6", exponent);
    for (float theta : kThetas) {
      const Vec3 wo = direction(theta);
      const auto chi2 = test::chi2_bsdf(*bsdf, wo, {}, {.sample_count = 200000, .bins_u = 40, .bins_v = 40});
      EXPECT_GT(chi2.p_value, kAlpha) << "n " << exponent << " theta " << theta << "\n" << chi2.report;
      const auto c = test::check_samples(*bsdf, wo, {}, 2000);
      EXPECT_GT(c.checked, 500);
      EXPECT_LT(c.max_f_error, 1e-6);
      EXPECT_LT(c.max_pdf_error, 1e-6);
      EXPECT_EQ(c.non_finite, 0);
      // The glossy lobe's part below the horizon is left out.
      const double integral = test::pdf_integral(*bsdf, wo, {});
      EXPECT_LE(integral, 1.0 + 1e-3) << "n " << exponent << " theta " << theta;
      if (theta == 0) {
        EXPECT_NEAR(integral, 1.0, 1e-3) << "n " << exponent;
      }
    }
  }
}

TEST(PhongBsdf, ConservesEnergyAndIsReciprocal) {
  for (float exponent : kExponents) {
    // kd + ks = 1: the most a valid Phong material reflects.
    const auto bsdf = phong("0.4", "0.6", exponent);
    for (float theta : kThetas) {
      const Vec3 wo = direction(theta);
      const auto a = test::albedo(*bsdf, wo, {}, 100000);
      EXPECT_LE(a.mean.r, 1.0f + 4 * a.standard_error.r) << "n " << exponent << " theta " << theta;
      EXPECT_GT(a.mean.r, 0.4f - 4 * a.standard_error.r);
      // albedo() underestimates only the glossy part cut off by the horizon.
      const Color reported = bsdf->albedo({}, wo);
      EXPECT_LE(reported.r, a.mean.r + 4 * a.standard_error.r + 1e-4f);
      EXPECT_LE(reported.r, 1.0f);
      if (theta == 0) {
        EXPECT_NEAR(reported.r, a.mean.r, 4 * a.standard_error.r + 1e-3f);
      }
    }
    EXPECT_LT(test::reciprocity_error(*bsdf, {}, 2000), 1e-4) << "n " << exponent;
  }
  // Normal incidence, exponent 0: the glossy lobe is a uniform hemisphere
  // times 2 cos(alpha)^0 / (2 pi), reflecting ks exactly.
  const auto flat = phong("0", "1", 0);
  const auto a = test::albedo(*flat, Vec3(0, 0, 1), {}, 100000);
  EXPECT_NEAR(a.mean.r, 1.0f, 4 * a.standard_error.r + 1e-4f);
}

TEST(PhongBsdf, ValueMatchesTheFormula) {
  const auto bsdf = phong("0.3", "0.5", 10);
  const Vec3 wo = direction(0.6f, 0.0f), wi = direction(0.9f, kPi);  // 0.3 rad from the mirror direction
  const float expected = 0.3f / kPi + 0.5f * 12 / (2 * kPi) * std::pow(std::cos(0.3f), 10.0f);
  EXPECT_NEAR(bsdf->eval({}, wo, wi).g, expected, 1e-5f);
  EXPECT_EQ(bsdf->eval({}, wo, Vec3(0, 0, -1)), Color());  // no transmission
  EXPECT_EQ(bsdf->eval({}, Vec3(0, 0, -1), wo), Color());  // one-sided
  EXPECT_EQ(bsdf->pdf({}, Vec3(0, 0, -1), wo), 0.0f);
  EXPECT_FALSE(bsdf->sample({}, Vec3(0, 0, -1), 0.5f, {0.5f, 0.5f}));
}

// Normalisation: seen from the normal, the glossy lobe ks (n + 2) / (2 pi)
// cos^n reflects exactly ks and the diffuse part exactly kd, at every
// exponent. The reflected energy is integrated from eval() alone, by the
// midpoint rule over the polar angle at several azimuths, independently
// of the sampling routine and of albedo().
TEST(PhongBsdf, LobesAreNormalisedAtEveryExponent) {
  const auto reflected = [](const Bsdf& bsdf) {
    constexpr int kSteps = 100000;
    const double h = (kPi / 2) / kSteps;
    double sum = 0;
    for (float phi : {0.0f, 1.3f, 4.0f})
      for (int i = 0; i < kSteps; ++i) {
        const double theta = (i + 0.5) * h;
        const Vec3 wi = direction(float(theta), phi);
        sum += bsdf.eval({}, Vec3(0, 0, 1), wi).g * std::cos(theta) * std::sin(theta) * h * 2 * kPi;
      }
    return sum / 3;
  };
  for (float exponent : {0.0f, 1.0f, 2.0f, 10.0f, 30.0f, 200.0f, 1000.0f}) {
    EXPECT_NEAR(reflected(*phong("0", "1", exponent)), 1.0, 1e-3) << "glossy, n " << exponent;
    EXPECT_NEAR(reflected(*phong("0.3", "0.5", exponent)), 0.8, 1e-3) << "both, n " << exponent;
  }
  EXPECT_NEAR(reflected(*phong("1", "0", 30)), 1.0, 1e-3) << "diffuse";
}

// Huge exponents, grazing directions and extreme random numbers stay
// finite; at normal incidence a lobe of exponent 1e4 or 1e6 lies wholly
// above the horizon, so the material reflects kd + ks = 1 (z-test at 4
// standard errors), its glossy samples within a degree of the normal.
TEST(PhongBsdf, HardCasesStayFiniteAndHugeExponentsKeepTheirEnergy) {
  for (float exponent : {0.0f, 1e4f, 1e6f}) {
    const auto bsdf = phong("0.1", "0.9", exponent);
    for (float theta : {0.0f, 1.5607f, 1.5707f}) {
      const Vec3 wo = direction(theta);
      for (float u_lobe : {0.0f, 0.5f, kOneMinusEpsilon})
        for (Vec2 u : {Vec2{0, 0}, Vec2{kOneMinusEpsilon, kOneMinusEpsilon}, Vec2{1e-30f, 0.5f}, Vec2{0.5f, 0.5f}}) {
          const auto s = bsdf->sample({}, wo, u_lobe, u);
          if (!s) continue;
          EXPECT_TRUE(s->f.is_finite() && std::isfinite(s->pdf) && is_finite(s->wi));
          EXPECT_GT(s->pdf, 0);
          EXPECT_GT(s->wi.z, 0);
        }
      const auto c = test::check_samples(*bsdf, wo, {}, 2000);
      EXPECT_EQ(c.non_finite, 0);
      EXPECT_TRUE(bsdf->eval({}, wo, Vec3(wo.x * -1, wo.y * -1, wo.z)).is_finite());
      if (theta == 0 && exponent > 0) {
        const auto a = test::albedo(*bsdf, wo, {}, 4000);
        EXPECT_NEAR(a.mean.r, 1.0, 4 * a.standard_error.r + 1e-4) << "n " << exponent;
        const auto glossy = bsdf->sample({}, wo, 0, {0.3f, 0.8f});
        ASSERT_TRUE(glossy);
        EXPECT_EQ(glossy->lobe, uint32_t(kGlossyReflection));
        EXPECT_GT(glossy->wi.z, std::cos(M_PI / 180)) << "n " << exponent;
      }
    }
  }
  // Black material: nothing sampled, nothing evaluated.
  const auto black = phong("0", "0", 30);
  EXPECT_FALSE(black->sample({}, direction(0.5f), 0.5f, {0.5f, 0.5f}));
  EXPECT_EQ(black->pdf({}, direction(0.5f), direction(0.7f)), 0.0f);
}

// Reflectances summing above 1 are scaled down by the largest sum, with a
// warning, as Mitsuba 0.x does; refused where ensure_energy_conservation is
// false.
TEST(PhongBsdf, EnergyGainIsScaledAwayOrRefused) {
  const std::string gaining =
      "<rgb name='diffuse_reflectance' value='0.5, 0.5, 0.9'/>\n<rgb name='specular_reflectance' value='0.2'/>\n";
  const auto scene = test::scene_from_xml(
      "<scene version='3.0.0'>\n<shape type='rectangle'>\n<bsdf type='phong'>\n" + gaining + "</bsdf></shape></scene>",
      "old.xml");
  EXPECT_THAT(scene.warnings,
              testing::Contains(HasSubstr("old.xml:5: parameter 'specular_reflectance' of bsdf 'phong': "
                                          "diffuse_reflectance + specular_reflectance is 1.100000 in channel 2; "
                                          "both are scaled by 0.909091")));
  // f = kd / pi + ks (n + 2) / (2 pi) cos^n(alpha), both divided by 1.1.
  const Bsdf& bsdf = *scene->shapes()[0]->bsdf();
  const Vec3 wo = direction(0.3f, 0.0f), wi = direction(0.4f, kPi);
  const double cos_alpha = dot(wi, Vec3(-wo.x, -wo.y, wo.z));
  for (int c = 0; c < 3; ++c) {
    const double kd = c == 2 ? 0.9 : 0.5;
    const double expected = (kd / kPi + 0.2 * 32 / (2 * kPi) * std::pow(cos_alpha, 30)) / 1.1;
    EXPECT_NEAR(bsdf.eval({}, wo, wi)[c], expected, 1e-5 * expected) << c;
  }
  const std::string message =
      test::load_error("<scene version='3.0.0'>\n<shape type='rectangle'>\n<bsdf type='phong'>\n" + gaining +
                           "<boolean name='ensure_energy_conservation' value='false'/></bsdf></shape></scene>",
                       "bad.xml");
  EXPECT_THAT(message, HasSubstr("bad.xml:5: parameter 'specular_reflectance' of bsdf 'phong': diffuse_reflectance + "
                                 "specular_reflectance is 1.100000 in channel 2; it must be at most 1 to conserve "
                                 "energy"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><shape type='rectangle'><bsdf type='phong'>"
                               "<float name='exponent' value='-1'/></bsdf></shape></scene>"),
              HasSubstr("exponent"));
  EXPECT_EQ(test::load_error("<scene version='3.0.0'><shape type='rectangle'><bsdf type='phong'>"
                             "<rgb name='diffuse_reflectance' value='0.5'/><rgb name='specular_reflectance' "
                             "value='0.5'/></bsdf></shape></scene>"),
            "");
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
