#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/bsdf/fresnel.h"
#include "tests/support/bsdf_checks.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using test::below;
using test::direction;
using test::kImportance;
using test::kRadiance;
using test::sample_weight;

// Chi-square tests of the lobe choice in this file: 4 angles x 2 sides (counted in kMaterialChi2Tests).
const double kAlpha = test::material_chi2_alpha();

std::shared_ptr<Bsdf> sheet(float eta) {
  return test::make_bsdf("<bsdf type='thindielectric'>" + test::ior_params(eta) + "</bsdf>");
}

// The sheet's reflectance summed bounce by bounce: R, then T R T, T R^3 T, ...
double sheet_reflectance(float cos_o, float eta) {
  const double R = fresnel_dielectric(cos_o, eta).F, T = 1 - R;
  double sum = R, path = T * T * R;
  for (int k = 0; k < 100000 && path > 1e-14; ++k, path *= R * R) sum += path;
  return sum;
}

TEST(ThinDielectricBsdf, LobesFollowTheInterreflectedFresnelTerms) {
  const auto bsdf = sheet(1.5f);
  for (bool back : {false, true})
    for (float theta : {0.0f, 0.6f, 1.2f, 1.5607f}) {
      const Vec3 wo = back ? below(direction(theta)) : direction(theta);
      const double R = sheet_reflectance(std::abs(wo.z), 1.5f);
      test::UniformSource u(11);
      const int n = 100000;
      std::vector<double> observed(2, 0), expected{n * R, n * (1 - R)};
      for (int i = 0; i < n; ++i) {
        const float u_lobe = u.next_1d();
        const auto s = bsdf->sample(kImportance, wo, u_lobe, u.next_2d());
        ASSERT_TRUE(s);
        EXPECT_EQ(s->eta, 1);
        EXPECT_NEAR(sample_weight(*s), 1, 1e-6f);
        if (s->is_transmission()) {
          observed[1] += 1;
          EXPECT_EQ(s->lobe, kDeltaTransmission);
          EXPECT_EQ(s->wi, -wo);  // no bending
          EXPECT_NEAR(s->pdf, 1 - R, 1e-6);
        } else {
          observed[0] += 1;
          EXPECT_EQ(s->lobe, kDeltaReflection);
          EXPECT_EQ(s->wi, Vec3(-wo.x, -wo.y, wo.z));
          EXPECT_NEAR(s->pdf, R, 1e-6);
        }
      }
      const auto chi2 = test::chi2_test_counts(observed, expected);
      EXPECT_GT(chi2.p_value, kAlpha) << "theta " << theta << " back " << back << "\n" << chi2.report;
    }
  // A sheet reflects more than one face: at normal incidence 2 R / (1 + R), R = 0.04.
  EXPECT_NEAR(bsdf->sample({}, Vec3(0, 0, 1), 0, {})->pdf, 0.08f / 1.04f, 1e-6f);
}

TEST(ThinDielectricBsdf, WhiteFurnaceInBothModes) {
  for (float eta : {1.5f, 1.33f, 0.7f}) {
    const auto bsdf = sheet(eta);
    for (bool back : {false, true})
      for (float theta : {0.0f, 0.5f, 1.0f, 1.5f, 1.5607f})
        for (const BsdfContext& ctx : {kRadiance, kImportance}) {
          const Vec3 wo = back ? below(direction(theta)) : direction(theta);
          // In and out of the same medium: R' + T' = 1 and no eta^2, in either mode.
          const auto a = test::albedo(*bsdf, wo, ctx, 20000);
          EXPECT_NEAR(a.mean.r, 1, 1e-5f) << "eta " << eta << " theta " << theta;
          EXPECT_NEAR(a.standard_error.r, 0, 1e-5f);
          EXPECT_NEAR(bsdf->albedo(ctx, wo).g, 1, 1e-6f);
          const auto r = bsdf->sample(kRadiance, wo, 0.9999f, {}), i = bsdf->sample(kImportance, wo, 0.9999f, {});
          if (r) {
            ASSERT_TRUE(i);
            EXPECT_EQ(r->f, i->f);
          }
        }
  }
}

TEST(ThinDielectricBsdf, TotalInternalReflectionAtTheFirstFace) {
  // Index lower inside than outside (an air gap in water): beyond asin(eta)
  // nothing enters, so everything is reflected and nothing is NaN.
  const auto bsdf = sheet(1 / 1.33f);
  for (float theta : {1.0f, 1.3f, 1.5607f})
    for (float u_lobe : {0.0f, 0.999999f}) {
      const auto s = bsdf->sample(kRadiance, direction(theta), u_lobe, {});
      ASSERT_TRUE(s);
      EXPECT_EQ(s->lobe, kDeltaReflection);
      EXPECT_EQ(s->pdf, 1);
      EXPECT_NEAR(sample_weight(*s), 1, 1e-6f);
    }
}

TEST(ThinDielectricBsdf, IndexMatchedAndDegenerateDirections) {
  const auto matched = sheet(1.0f);
  for (float theta : {0.0f, 1.0f, 1.5607f}) {
    const auto s = matched->sample(kRadiance, direction(theta), 0, {});
    ASSERT_TRUE(s);
    EXPECT_EQ(s->lobe, kDeltaTransmission);
    EXPECT_EQ(s->wi, -direction(theta));
    EXPECT_EQ(s->pdf, 1);
    EXPECT_FLOAT_EQ(sample_weight(*s), 1);
  }
  const auto bsdf = test::make_bsdf("<bsdf type='thindielectric'/>");
  EXPECT_EQ(bsdf->lobes(), kDeltaReflection | kDeltaTransmission);
  EXPECT_EQ(bsdf->eval({}, direction(0.3f), -direction(0.3f)), Color());
  EXPECT_EQ(bsdf->pdf({}, direction(0.3f), -direction(0.3f)), 0);
  EXPECT_FALSE(bsdf->sample({}, Vec3(1, 0, 0), 0.5f, {}));
  for (float z : {1e-3f, 1e-6f, 1e-12f, -1e-12f, -1e-6f}) {
    const Vec3 wo = normalize(Vec3(std::sqrt(1 - z * z), 0, z));
    EXPECT_EQ(test::check_samples(*bsdf, wo, kRadiance, 1000).non_finite, 0) << z;
  }
}

TEST(ThinDielectricBsdf, SpecularScalesApplyPerLobe) {
  const auto bsdf = test::make_bsdf(
      "<bsdf type='thindielectric'><rgb name='specular_reflectance' value='0.5, 0.25, 1'/>"
      "<rgb name='specular_transmittance' value='0.2, 0.4, 0.8'/></bsdf>");
  const Vec3 wo = direction(0.6f);
  const auto r = bsdf->sample(kImportance, wo, 0, {}), t = bsdf->sample(kImportance, wo, 0.999f, {});
  ASSERT_TRUE(r && t);
  EXPECT_NEAR(sample_weight(*r), 0.25f, 1e-6f);
  EXPECT_NEAR(t->f.b * std::abs(t->wi.z) / t->pdf, 0.8f, 1e-6f);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
