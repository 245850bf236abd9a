#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/bsdf/fresnel.h"
#include "tests/support/bsdf_checks.h"
#include "tests/support/microfacet_oracle.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using test::below;
using test::direction;
using test::kImportance;
using test::kRadiance;
using test::sample_weight;

// Chi-square tests of the lobe choice in this file: 4 incident angles from
// outside, 2 from inside (the others reflect totally) (counted in kMaterialChi2Tests).
const double kAlpha = test::material_chi2_alpha();

std::shared_ptr<Bsdf> glass(float eta) {
  return test::make_bsdf("<bsdf type='dielectric'>" + test::ior_params(eta) + "</bsdf>");
}

TEST(DielectricBsdf, ReflectsAndRefractsWithFresnelProbabilities) {
  const auto bsdf = glass(1.5f);
  for (bool inside : {false, true})
    for (float theta : {0.0f, 0.5f, 1.2f, 1.5607f}) {  // inside, 0.5 is below and 1.2 beyond the critical angle
      const Vec3 wo = inside ? below(direction(theta)) : direction(theta);
      const float F = fresnel_dielectric(wo.z, 1.5f).F;
      test::UniformSource u(7);
      const int n = 100000;
      std::vector<double> observed(2, 0), expected{n * F, n * (1.0 - F)};
      for (int i = 0; i < n; ++i) {
        const float u_lobe = u.next_1d();
        const auto s = bsdf->sample(kImportance, wo, u_lobe, u.next_2d());
        ASSERT_TRUE(s);
        ASSERT_TRUE(s->is_delta());
        if (s->is_transmission()) {
          observed[1] += 1;
          EXPECT_EQ(s->lobe, kDeltaTransmission);
          EXPECT_LT(s->wi.z * wo.z, 0);
          // Snell's law, in the plane of incidence.
          const float eta_o = inside ? 1.5f : 1, eta_i = inside ? 1 : 1.5f;
          EXPECT_NEAR(eta_i * std::hypot(s->wi.x, s->wi.y), eta_o * std::hypot(wo.x, wo.y), 1e-5f);
          EXPECT_NEAR(s->wi.x * wo.y - s->wi.y * wo.x, 0, 1e-6f);
          EXPECT_LT(s->wi.x * wo.x + s->wi.y * wo.y, 1e-7f);
          EXPECT_FLOAT_EQ(s->eta, eta_i / eta_o);
          EXPECT_FLOAT_EQ(s->pdf, 1 - F);
        } else {
          observed[0] += 1;
          EXPECT_EQ(s->lobe, kDeltaReflection);
          EXPECT_EQ(s->wi, Vec3(-wo.x, -wo.y, wo.z));
          EXPECT_EQ(s->eta, 1);
          EXPECT_FLOAT_EQ(s->pdf, F);
        }
        EXPECT_NEAR(sample_weight(*s), 1, 1e-6f);  // importance: every sample carries exactly 1
        EXPECT_NEAR(length(s->wi), 1, 1e-6f);
      }
      if (F == 1) {  // total internal reflection
        EXPECT_EQ(observed[1], 0);
        continue;
      }
      const auto chi2 = test::chi2_test_counts(observed, expected);
      EXPECT_GT(chi2.p_value, kAlpha) << "theta " << theta << " inside " << inside << "\n" << chi2.report;
    }
}

TEST(DielectricBsdf, DeltaLobesHaveNoDensity) {
  const auto bsdf = test::make_bsdf("<bsdf type='dielectric'/>");
  EXPECT_EQ(bsdf->lobes(), kDeltaReflection | kDeltaTransmission);
  const Vec3 wo = direction(0.4f);
  EXPECT_EQ(bsdf->eval({}, wo, Vec3(-wo.x, -wo.y, wo.z)), Color());
  EXPECT_EQ(bsdf->pdf({}, wo, Vec3(-wo.x, -wo.y, wo.z)), 0);
  EXPECT_EQ(bsdf->pdf({}, wo, -wo), 0);
  EXPECT_EQ(test::pdf_integral(*bsdf, wo, {}), 0);
  // Defaults: bk7 in air.
  const float F0 = std::pow((1.5046f / 1.00028f - 1) / (1.5046f / 1.00028f + 1), 2.0f);
  EXPECT_NEAR(bsdf->albedo({}, Vec3(0, 0, 1)).r, 1, 1e-6f);
  const auto s = bsdf->sample({}, Vec3(0, 0, 1), 0.5f * F0, {});
  ASSERT_TRUE(s);
  EXPECT_EQ(s->lobe, kDeltaReflection);
  EXPECT_NEAR(s->pdf, F0, 1e-6f);
  const auto named = test::make_bsdf("<bsdf type='dielectric'><string name='int_ior' value='water'/></bsdf>");
  const auto t = named->sample({}, Vec3(0, 0, 1), 0.99f, {});
  ASSERT_TRUE(t);
  EXPECT_NEAR(t->eta, 1.333f / 1.00028f, 1e-5f);
}

TEST(DielectricBsdf, RadianceIsScaledByEtaSquaredAcrossRefraction) {
  for (float eta : {1.5f, 1.33f, 0.8f}) {
    const auto bsdf = glass(eta);
    for (bool inside : {false, true}) {
      const Vec3 wo = inside ? below(direction(0.3f)) : direction(0.3f);
      const auto r = bsdf->sample(kRadiance, wo, 0.999f, {});
      const auto i = bsdf->sample(kImportance, wo, 0.999f, {});
      ASSERT_TRUE(r && i);
      ASSERT_TRUE(r->is_transmission() && i->is_transmission());
      const float eta_wi_over_wo = inside ? 1 / eta : eta;
      EXPECT_FLOAT_EQ(r->eta, eta_wi_over_wo);
      EXPECT_EQ(r->wi, i->wi);
      EXPECT_EQ(r->pdf, i->pdf);
      // Radiance entering the denser medium is concentrated by eta^2; seen
      // backwards along the path, the weight is divided by it.
      EXPECT_NEAR(r->f.r / i->f.r, 1 / (eta_wi_over_wo * eta_wi_over_wo), 1e-5f);
      // Reflection is the same in both modes.
      const auto rr = bsdf->sample(kRadiance, wo, 0, {}), ri = bsdf->sample(kImportance, wo, 0, {});
      ASSERT_TRUE(rr && ri);
      EXPECT_EQ(rr->f, ri->f);
    }
  }
}

TEST(DielectricBsdf, WhiteFurnace) {
  const auto bsdf = glass(1.5f);
  for (bool inside : {false, true})
    for (float theta : {0.0f, 0.5f, 1.0f, 1.5f, 1.5607f}) {
      const Vec3 wo = inside ? below(direction(theta)) : direction(theta);
      // Importance: R + T = 1 with every sample weighing exactly 1.
      const auto a = test::albedo(*bsdf, wo, kImportance, 20000);
      EXPECT_NEAR(a.mean.r, 1, 1e-5f) << theta;
      EXPECT_NEAR(a.standard_error.r, 0, 1e-5f);
      EXPECT_NEAR(bsdf->albedo(kRadiance, wo).g, 1, 1e-6f);
      // Radiance: the documented F + (1 - F) / eta^2, eta along wi.
      const auto fr = fresnel_dielectric(wo.z, 1.5f);
      const double expected = fr.F + (1 - fr.F) * fr.eta_ti * fr.eta_ti;
      const auto r = test::albedo(*bsdf, wo, kRadiance, 100000);
      EXPECT_NEAR(r.mean.r, expected, 5 * r.standard_error.r + 1e-5) << theta << " inside " << inside;
    }
}

TEST(DielectricBsdf, TotalInternalReflection) {
  const auto bsdf = glass(1.5f);
  const float critical = std::asin(1 / 1.5f);
  for (float theta : {critical + 1e-3f, 1.0f, 1.3f, 1.5607f}) {
    const Vec3 wo = below(direction(theta));
    for (float u_lobe : {0.0f, 0.5f, 0.999999f})
      for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
        const auto s = bsdf->sample({mode, {}}, wo, u_lobe, {0.3f, 0.6f});
        ASSERT_TRUE(s);
        EXPECT_EQ(s->lobe, kDeltaReflection);
        EXPECT_EQ(s->pdf, 1);
        EXPECT_EQ(s->wi, Vec3(-wo.x, -wo.y, wo.z));
        EXPECT_NEAR(sample_weight(*s), 1, 1e-6f);
      }
  }
}

// An interior less dense than the outside (int_ior 0.763, ext_ior 1: air
// in ice) reflects totally light arriving from outside beyond asin(0.763),
// and refracts away from the normal below it.
TEST(DielectricBsdf, ALessDenseInteriorReflectsTotallyFromOutside) {
  const auto bsdf = test::make_bsdf(
      "<bsdf type='dielectric'><float name='int_ior' value='0.763'/><float name='ext_ior' value='1'/></bsdf>");
  const float critical = std::asin(0.763f);
  for (float theta : {critical + 1e-3f, 1.2f}) {
    const Vec3 wo = direction(theta);
    for (float u_lobe : {0.0f, 0.5f, 0.999999f}) {
      const auto s = bsdf->sample(kImportance, wo, u_lobe, {0.3f, 0.6f});
      ASSERT_TRUE(s);
      EXPECT_EQ(s->lobe, kDeltaReflection);
      EXPECT_NEAR(sample_weight(*s), 1, 1e-6f);
    }
  }
  const Vec3 wo = direction(0.5f);
  const auto t = bsdf->sample(kImportance, wo, 0.999999f, {0.3f, 0.6f});
  ASSERT_TRUE(t);
  ASSERT_EQ(t->lobe, kDeltaTransmission);
  EXPECT_NEAR(0.763f * std::hypot(t->wi.x, t->wi.y), std::hypot(wo.x, wo.y), 1e-5f);  // Snell
  EXPECT_GT(std::hypot(t->wi.x, t->wi.y), std::hypot(wo.x, wo.y));
}

TEST(DielectricBsdf, IndexMatchedPassesStraightThrough) {
  const auto bsdf = test::make_bsdf(
      "<bsdf type='dielectric'><string name='int_ior' value='water'/><string name='ext_ior' value='water'/></bsdf>");
  for (bool inside : {false, true})
    for (float theta : {0.0f, 0.7f, 1.5607f, 1.5707f})
      for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance})
        for (float u_lobe : {0.0f, 0.5f, 0.999f}) {
          const Vec3 wo = inside ? below(direction(theta)) : direction(theta);
          const auto s = bsdf->sample({mode, {}}, wo, u_lobe, {});
          ASSERT_TRUE(s);
          EXPECT_EQ(s->lobe, kDeltaTransmission);
          EXPECT_EQ(s->wi, -wo);
          EXPECT_EQ(s->pdf, 1);
          EXPECT_EQ(s->eta, 1);
          EXPECT_FLOAT_EQ(sample_weight(*s), 1);
          EXPECT_EQ(bsdf->albedo({mode, {}}, wo).b, 1);
        }
}

// Finite, and the furnace equal to what Fresnel's equations (written in the
// test's oracle) give, at normal incidence, at grazing angles from both sides (total internal reflection
// included) and for an index of almost one.
TEST(DielectricBsdf, FiniteAtGrazingAndNormalIncidence) {
  for (float eta : {1.5f, 1.0001f, 0.6f}) {
    const auto bsdf = glass(eta);
    for (float z : {1.0f, 1e-3f, 1e-6f, 1e-12f, -1e-12f, -1e-6f, -1e-3f, -1.0f})
      for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
        const Vec3 wo = normalize(Vec3(std::sqrt(std::max(0.0f, 1 - z * z)), 0, z));
        const auto c = test::check_samples(*bsdf, wo, {mode, {}}, 1000);
        EXPECT_EQ(c.non_finite, 0) << "eta " << eta << " z " << z;
        const auto a = test::albedo(*bsdf, wo, {mode, {}}, 1000);
        // Importance: every sample's weight is one. Radiance: refraction
        // scales by 1 / eta^2, eta across over eta on wo's side.
        const double relative = z > 0 ? eta : 1 / eta, R = test::fresnel_reflectance(std::abs(wo.z), relative);
        const double expected = mode == TransportMode::Importance ? 1 : R + (1 - R) / (relative * relative);
        EXPECT_NEAR(a.mean.r, expected, 4 * a.standard_error.r + 1e-5)
            << "eta " << eta << " z " << z << (mode == TransportMode::Importance ? " importance" : " radiance");
      }
    EXPECT_FALSE(bsdf->sample({}, Vec3(1, 0, 0), 0.5f, {}));  // in the tangent plane
  }
}

TEST(DielectricBsdf, SpecularScalesApplyPerLobe) {
  const auto bsdf = test::make_bsdf(
      "<bsdf type='dielectric'><rgb name='specular_reflectance' value='0.5, 0.25, 1'/>"
      "<rgb name='specular_transmittance' value='0.2, 0.4, 0.8'/></bsdf>");
  const Vec3 wo = direction(0.6f);
  const auto r = bsdf->sample(kImportance, wo, 0, {}), t = bsdf->sample(kImportance, wo, 0.999f, {});
  ASSERT_TRUE(r && t);
  EXPECT_NEAR(r->f.g * std::abs(r->wi.z) / r->pdf, 0.25f, 1e-6f);
  EXPECT_NEAR(t->f.b * std::abs(t->wi.z) / t->pdf, 0.8f, 1e-6f);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
