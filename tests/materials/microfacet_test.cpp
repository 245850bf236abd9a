#include "core/bsdf/microfacet.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/bsdf_checks.h"
#include "tests/support/microfacet_oracle.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using Type = MicrofacetDistribution::Type;

struct Case {
  Type type;
  float alpha_u, alpha_v;
};

const Case kCases[] = {{Type::GGX, 0.1f, 0.1f},      {Type::GGX, 0.5f, 0.5f},      {Type::GGX, 0.05f, 0.6f},
                       {Type::Beckmann, 0.1f, 0.1f}, {Type::Beckmann, 0.7f, 0.7f}, {Type::Beckmann, 0.3f, 0.05f}};
const float kThetas[] = {0.0f, 0.8f, 1.5f, 1.5607f};
// Chi-square tests in this file: every case at every angle, and every
// case's sample_D (counted in kMaterialChi2Tests).
const double kAlpha = test::material_chi2_alpha();

class Microfacet : public testing::TestWithParam<Case> {};

// The projected microfacet area is the macro-surface's: integral of D cos = 1.
TEST_P(Microfacet, ProjectedAreaIsOne) {
  const MicrofacetDistribution d(GetParam().type, GetParam().alpha_u, GetParam().alpha_v);
  const double integral =
      test::integrate_sphere([&](const Vec3& m) { return double(d.D(m)) * std::max(0.0f, m.z); }, 80, 80);
  EXPECT_NEAR(integral, 1.0, 2e-3);
}

// Smith masking is consistent with D: the visible projected area of the
// microfacets seen from wo is the macro-surface's, wo.z.
TEST_P(Microfacet, VisibleAreaMatchesMasking) {
  const MicrofacetDistribution d(GetParam().type, GetParam().alpha_u, GetParam().alpha_v);
  for (float theta : kThetas) {
    const Vec3 wo = test::direction(theta, 0.7f);
    const double visible = test::integrate_sphere(
        [&](const Vec3& m) { return double(d.G1(wo, m)) * std::max(0.0f, dot(wo, m)) * d.D(m); }, 80, 80);
    EXPECT_NEAR(visible, wo.z, 3e-3) << "theta " << theta;
  }
}

// Fine bins along cos(theta): the quadrature of the expected counts must
// resolve the peak of alpha = 0.1 to 1e-5.
TEST_P(Microfacet, SamplesFollowThePdf) {
  const MicrofacetDistribution d(GetParam().type, GetParam().alpha_u, GetParam().alpha_v);
  for (float theta : kThetas) {
    const Vec3 wi = test::direction(theta, 0.7f);
    EXPECT_NEAR(test::integrate_sphere([&](const Vec3& m) { return double(d.pdf(wi, m)); }, 80, 80), 1.0, 3e-3);
    const auto chi2 = test::chi2_test_sphere(
        [&](test::UniformSource& u) -> std::optional<Vec3> { return d.sample(wi, u.next_2d()); },
        [&](const Vec3& m) { return double(d.pdf(wi, m)); }, {.sample_count = 300000, .bins_u = 80, .bins_v = 40});
    EXPECT_GT(chi2.p_value, kAlpha) << "theta " << theta << "\n" << chi2.report;
  }
}

TEST_P(Microfacet, NormalSamplesFollowD) {
  const MicrofacetDistribution d(GetParam().type, GetParam().alpha_u, GetParam().alpha_v);
  EXPECT_NEAR(test::integrate_sphere([&](const Vec3& m) { return double(d.pdf_D(m)); }, 80, 80), 1.0, 3e-3);
  const auto chi2 = test::chi2_test_sphere(
      [&](test::UniformSource& u) -> std::optional<Vec3> { return d.sample_D(u.next_2d()); },
      [&](const Vec3& m) { return double(d.pdf_D(m)); }, {.sample_count = 300000, .bins_u = 40, .bins_v = 40});
  EXPECT_GT(chi2.p_value, kAlpha) << chi2.report;
}

// Sampled normals are unit length, above the surface and finite, even for
// nearly smooth surfaces seen at grazing angles.
TEST_P(Microfacet, SamplesAreValidNormals) {
  for (float scale : {1.0f, 1e-3f}) {
    const MicrofacetDistribution d(GetParam().type, GetParam().alpha_u * scale, GetParam().alpha_v * scale);
    test::UniformSource u(7);
    for (float theta : {0.0f, 1.0f, 1.5607f, 1.5707f})
      for (int i = 0; i < 2000; ++i) {
        const Vec3 wi = test::direction(theta, 0.7f);
        for (const Vec3 m : {d.sample(wi, u.next_2d()), d.sample_D(u.next_2d())}) {
          ASSERT_TRUE(is_finite(m)) << theta;
          EXPECT_NEAR(length(m), 1.0f, 1e-5f);
          EXPECT_GT(m.z, 0.0f);
        }
      }
  }
}

INSTANTIATE_TEST_SUITE_P(Distributions, Microfacet, testing::ValuesIn(kCases));

// Smith's Lambda in closed form (tests/support/microfacet_oracle). G1 is
// 1 / (1 + Lambda) for a facet facing w, and the height-correlated G of a
// pair is 1 / (1 + Lambda(wo) + Lambda(wi)), never the product of the
// G1s and never G1 squared; a facet turned away from either direction
// masks it completely.
TEST(Microfacet, SmithMaskingMatchesItsClosedForms) {
  const auto lambda = [](Type type, double alpha, Vec3 w) {
    return test::smith_lambda({type == Type::GGX, alpha, alpha}, w);
  };
  for (const Type type : {Type::GGX, Type::Beckmann})
    for (const float alpha : {0.05f, 0.3f, 0.9f}) {
      const MicrofacetDistribution d(type, alpha, alpha);
      for (const float to : {0.0f, 0.6f, 1.2f, 1.5f})
        for (const float ti : {0.3f, 1.0f, 1.45f}) {
          const Vec3 wo = test::direction(to, 0.4f), wi = test::direction(ti, 2.9f), m = normalize(wo + wi);
          const double lo = lambda(type, alpha, wo), li = lambda(type, alpha, wi);
          EXPECT_NEAR(d.lambda(wo), lo, 1e-4 * (1 + lo)) << alpha << " " << to;
          EXPECT_NEAR(d.G1(wo, m), 1 / (1 + lo), 1e-5) << alpha << " " << to;
          EXPECT_NEAR(d.G(wo, wi, m), 1 / (1 + lo + li), 1e-5) << alpha << " " << to << " " << ti;
          const Vec3 away = test::direction(1.2f, 0.4f + float(M_PI));  // a facet tilted away from wo
          if (dot(wo, away) < 0) {
            EXPECT_EQ(d.G1(wo, away), 0);
          }
        }
    }
}

TEST(Microfacet, ParsesItsNames) {
  EXPECT_EQ(MicrofacetDistribution::parse_type("ggx"), Type::GGX);
  EXPECT_EQ(MicrofacetDistribution::parse_type("beckmann"), Type::Beckmann);
  EXPECT_THROW(MicrofacetDistribution::parse_type("phong"), std::invalid_argument);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
