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
const char* const kDistributions[] = {"beckmann", "ggx"};
const float kAlphas[] = {0.05f, 0.3f, 0.8f};

// Chi-square tests in this file: 2 distributions x 3 roughnesses x 4 incident angles, and 2 incident angles
// sampling all facet normals (counted in kMaterialChi2Tests).
const double kAlpha = test::material_chi2_alpha();

std::shared_ptr<Bsdf> rough(const std::string& distribution, float alpha, const std::string& extra = "") {
  return test::make_bsdf("<bsdf type='roughplastic'><string name='distribution' value='" + distribution +
                         "'/><float name='alpha' value='" + std::to_string(alpha) + "'/>" + extra + "</bsdf>");
}

const std::string kColoured =
    "<rgb name='diffuse_reflectance' value='0.1, 0.5, 0.9'/><rgb name='specular_reflectance' value='0.6'/>";
const std::string kWhite = "<rgb name='diffuse_reflectance' value='1'/>";

TEST(RoughPlasticBsdf, SamplesFollowThePdf) {
  for (const char* distribution : kDistributions)
    for (float alpha : kAlphas) {
      const auto bsdf = rough(distribution, alpha, kColoured);
      for (float theta : kThetas) {
        const Vec3 wo = direction(theta);
        // 80 azimuth bins: with 40, the bin integration of chi2.cpp misses part of
        // the Beckmann alpha = 0.05 peak at the horizon near grazing (the pdf
        // integrates to 0.627 there instead of 0.661, which integrate_sphere and
        // the sampler's own success rate both give).
        const auto chi2 = test::chi2_bsdf(*bsdf, wo, {}, {.sample_count = 200000, .bins_u = 40, .bins_v = 80});
        EXPECT_GT(chi2.p_value, kAlpha) << distribution << " " << alpha << " theta " << theta << "\n" << chi2.report;
        const auto c = test::check_samples(*bsdf, wo, {}, 2000);
        EXPECT_GT(c.checked, 1000);
        EXPECT_LT(c.max_f_error, 1e-6);
        EXPECT_LT(c.max_pdf_error, 1e-6);
        EXPECT_EQ(c.non_finite, 0);
        // Reflections below the horizon are left out.
        const double integral = test::pdf_integral(*bsdf, wo, {});
        EXPECT_LE(integral, 1.0 + 1e-3) << distribution << " " << alpha << " theta " << theta;
        EXPECT_GT(integral, 0.5) << distribution << " " << alpha << " theta " << theta;
      }
    }
}

// sample_visible = false draws facet normals from D(m) cos(theta_m) instead:
// the same material (eval unchanged), a different but consistent sampler.
TEST(RoughPlasticBsdf, SamplingAllFacetNormals) {
  const auto visible = rough("ggx", 0.3f, kColoured);
  const auto all = rough("ggx", 0.3f, kColoured + "<boolean name='sample_visible' value='false'/>");
  for (float theta : {0.3f, 1.3f}) {
    const Vec3 wo = direction(theta);
    const auto chi2 = test::chi2_bsdf(*all, wo, {}, {.sample_count = 200000, .bins_u = 40, .bins_v = 80});
    EXPECT_GT(chi2.p_value, kAlpha) << "theta " << theta << "\n" << chi2.report;
    const auto c = test::check_samples(*all, wo, {}, 2000);
    EXPECT_LT(c.max_f_error, 1e-6);
    EXPECT_LT(c.max_pdf_error, 1e-6);
    const Vec3 wi = direction(0.5f, 2.5f);
    EXPECT_EQ(all->eval({}, wo, wi), visible->eval({}, wo, wi));
    EXPECT_NE(all->pdf({}, wo, wi), visible->pdf({}, wo, wi));
  }
}

TEST(RoughPlasticBsdf, WhiteFurnace) {
  // A white base and coating absorb nothing: by construction all light comes
  // back, up to the tabulation of the coating's albedo, from near-smooth to
  // very rough coatings.
  for (const char* distribution : kDistributions)
    for (float alpha : {1e-4f, 0.05f, 0.3f, 0.8f, 1.0f})
      for (const char* nonlinear : {"false", "true"}) {
        const auto white = rough(distribution, alpha, kWhite + "<boolean name='nonlinear' value='" + nonlinear + "'/>");
        for (float theta : kThetas) {
          const Vec3 wo = direction(theta);
          const auto a = test::albedo(*white, wo, {}, 50000);
          EXPECT_LE(a.mean.r, 1.0f + 4 * a.standard_error.r + 2e-3f)
              << distribution << " " << alpha << " theta " << theta;
          EXPECT_NEAR(a.mean.r, 1.0f, 4 * a.standard_error.r + 5e-3f)
              << distribution << " " << alpha << " theta " << theta;
          EXPECT_LE(white->albedo({}, wo).r, 1.0f + 1e-5f);
        }
      }
}

TEST(RoughPlasticBsdf, AlbedoAndReciprocity) {
  for (const char* distribution : kDistributions)
    for (float alpha : kAlphas) {
      const auto bsdf = rough(distribution, alpha, kColoured + "<boolean name='nonlinear' value='true'/>");
      for (float theta : kThetas) {
        const Vec3 wo = direction(theta);
        const auto a = test::albedo(*bsdf, wo, {}, 50000);
        const Color reported = bsdf->albedo({}, wo);
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(reported[c], a.mean[c], 4 * a.standard_error[c] + 5e-3f)
              << distribution << " " << alpha << " theta " << theta << " channel " << c;
      }
      EXPECT_LT(test::reciprocity_error(*bsdf, {}, 2000), 1e-4) << distribution << " " << alpha;
      EXPECT_EQ(bsdf->eval({}, direction(0.3f), Vec3(0, 0, -1)), Color());  // no transmission
      EXPECT_EQ(bsdf->eval({}, Vec3(0, 0, -1), direction(0.3f)), Color());  // one-sided
      EXPECT_EQ(bsdf->pdf({}, Vec3(0, 0, -1), direction(0.3f)), 0.0f);
      EXPECT_FALSE(bsdf->sample({}, Vec3(0, 0, -1), 0.5f, {0.5f, 0.5f}));
    }
}

TEST(RoughPlasticBsdf, SmoothLimitIsPlastic) {
  // Away from the mirror direction only the diffuse parts remain; they agree
  // as the roughness goes to 0.
  const std::string params = kColoured + "<boolean name='nonlinear' value='true'/><float name='int_ior' value='1.7'/>";
  const auto smooth = test::make_bsdf("<bsdf type='plastic'>" + params + "</bsdf>");
  for (const char* distribution : kDistributions) {
    const auto bsdf = rough(distribution, 1e-4f, params);
    for (float theta_o : {0.1f, 0.8f, 1.3f})
      for (float theta_i : {0.3f, 1.0f, 1.5f}) {
        const Vec3 wo = direction(theta_o, 0.3f), wi = direction(theta_i, 2.0f);
        const Color a = bsdf->eval({}, wo, wi), b = smooth->eval({}, wo, wi);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 0.01f * b[c]) << distribution << " " << theta_o;
        EXPECT_NEAR(bsdf->albedo({}, wo).g, smooth->albedo({}, wo).g, 5e-3f);
      }
  }
}

TEST(RoughPlasticBsdf, HardCasesStayFinite) {
  for (const char* distribution : kDistributions)
    for (float alpha : {0.0f, 1e-4f, 1.0f, 3.0f}) {
      const auto bsdf = rough(distribution, alpha, kColoured);
      for (float theta : {0.0f, 1.5607f, 1.5707f}) {
        const Vec3 wo = direction(theta);
        for (float u_lobe : {0.0f, 0.5f, kOneMinusEpsilon})
          for (Vec2 u : {Vec2{0, 0}, Vec2{kOneMinusEpsilon, kOneMinusEpsilon}, Vec2{0.5f, 0.5f}}) {
            const auto s = bsdf->sample({}, wo, u_lobe, u);
            if (!s) continue;
            EXPECT_TRUE(s->f.is_finite() && std::isfinite(s->pdf) && is_finite(s->wi)) << distribution << alpha;
            EXPECT_GT(s->pdf, 0);
          }
        const auto c = test::check_samples(*bsdf, wo, {}, 2000);
        EXPECT_EQ(c.non_finite, 0) << distribution << " " << alpha << " theta " << theta;
        EXPECT_LT(c.max_f_error, 1e-6);
        EXPECT_TRUE(bsdf->albedo({}, wo).is_finite());
        EXPECT_TRUE(bsdf->eval({}, wo, Vec3(-wo.x, -wo.y, wo.z)).is_finite());
        EXPECT_TRUE(std::isfinite(bsdf->pdf({}, wo, Vec3(-wo.x, -wo.y, wo.z))));
      }
    }
  const auto black = rough("ggx", 0.3f,
                           "<rgb name='diffuse_reflectance' value='0'/><rgb name='specular_reflectance' "
                           "value='0'/>");
  EXPECT_FALSE(black->sample({}, direction(0.5f), 0.5f, {0.5f, 0.5f}));
  EXPECT_EQ(black->pdf({}, direction(0.5f), direction(0.7f)), 0.0f);
}

TEST(RoughPlasticBsdf, BadParametersNameThemselves) {
  EXPECT_THAT(test::load_error("<scene version='3.0.0'>\n<shape type='rectangle'>\n<bsdf type='roughplastic'>\n"
                               "<string name='distribution' value='phong'/></bsdf></shape></scene>",
                               "bad.xml"),
              HasSubstr("distribution must be beckmann or ggx"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><shape type='rectangle'><bsdf type='roughplastic'>"
                               "<float name='alpha' value='-0.1'/></bsdf></shape></scene>"),
              HasSubstr("alpha"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
