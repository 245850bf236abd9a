#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "core/math/constants.h"
#include "tests/support/bsdf_checks.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using test::direction;

// Chi-square tests in this file: 3 incident angles x 2 opacities (counted in kMaterialChi2Tests).
const double kAlpha = test::material_chi2_alpha();

std::string masked_diffuse(const std::string& opacity) {
  return "<bsdf type='mask'>" + opacity +
         "<bsdf type='diffuse'><rgb name='reflectance' value='0.2, 0.5, 0.8'/></bsdf></bsdf>";
}

TEST(MaskBsdf, SamplesFollowThePdf) {
  for (float a : {0.3f, 0.9f}) {
    const auto bsdf = test::make_bsdf(masked_diffuse("<float name='opacity' value='" + std::to_string(a) + "'/>"));
    EXPECT_EQ(bsdf->lobes(), uint32_t(kDiffuseReflection | kDeltaTransmission));
    for (float theta : {0.0f, 0.8f, 1.5f}) {
      const BsdfContext ctx{};
      const Vec3 wo = direction(theta);
      const auto chi2 = test::chi2_bsdf(*bsdf, wo, ctx, {.sample_count = 200000, .bins_u = 20, .bins_v = 40});
      EXPECT_GT(chi2.p_value, kAlpha) << "opacity " << a << " theta " << theta << "\n" << chi2.report;
      const auto c = test::check_samples(*bsdf, wo, ctx, 4000);
      EXPECT_NEAR(c.checked / 4000.0, a, 0.05);
      EXPECT_LT(c.max_f_error, 1e-6);
      EXPECT_LT(c.max_pdf_error, 1e-5);
      EXPECT_EQ(c.non_finite, 0);
      EXPECT_NEAR(test::pdf_integral(*bsdf, wo, ctx), a, 1e-3);
      // eval is the nested diffuse scaled by the opacity.
      EXPECT_NEAR(bsdf->eval(ctx, wo, direction(0.5f, 2.0f)).g, a * 0.5f * kInvPi, 1e-6f);
    }
  }
}

TEST(MaskBsdf, PassThroughIsAnIndexMatchedDeltaTransmission) {
  const auto bsdf = test::make_bsdf(masked_diffuse("<float name='opacity' value='0.25'/>"));
  const Vec3 wo = direction(1.1f, 0.7f);
  int through = 0;
  for (int i = 0; i < 100; ++i) {
    const float u_lobe = (i + 0.5f) / 100;
    const auto s = bsdf->sample({}, wo, u_lobe, {0.3f, 0.6f});
    ASSERT_TRUE(s);
    if (!s->is_delta()) continue;
    ++through;
    EXPECT_EQ(s->lobe, uint32_t(kDeltaTransmission));
    EXPECT_EQ(s->wi, -wo);
    EXPECT_EQ(s->eta, 1.0f);
    EXPECT_NEAR(s->pdf, 0.75f, 1e-6f);
    EXPECT_NEAR(s->f.r * std::abs(s->wi.z) / s->pdf, 1.0f, 1e-6f);  // weight 1: light continues unchanged
    EXPECT_EQ(bsdf->eval({}, wo, s->wi), Color());                  // delta: never evaluated
    EXPECT_EQ(bsdf->pdf({}, wo, s->wi), 0.0f);
  }
  EXPECT_EQ(through, 75);
}

TEST(MaskBsdf, AlbedoMixesNestedAndPassThrough) {
  const auto bsdf = test::make_bsdf(masked_diffuse("<float name='opacity' value='0.4'/>"));
  for (float theta : {0.2f, 1.0f, 1.5f}) {
    const auto a = test::albedo(*bsdf, direction(theta), {}, 200000);
    const Color expected = Color(0.2f, 0.5f, 0.8f) * 0.4f + Color(0.6f);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a.mean[c], expected[c], 5 * a.standard_error[c] + 1e-6f) << theta;
    const Color exact = bsdf->albedo({}, direction(theta));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(exact[c], expected[c], 1e-6f);
  }
  // Seen from below, the diffuse side absorbs and only the pass-through remains.
  const auto below = test::albedo(*bsdf, Vec3(0.3f, 0, -std::sqrt(1 - 0.09f)), {}, 10000);
  EXPECT_NEAR(below.mean.r, 0.6f, 5 * below.standard_error.r);
  EXPECT_NEAR(bsdf->albedo({}, Vec3(0, 0, -1)).r, 0.6f, 1e-6f);
}

TEST(MaskBsdf, OpacityZeroAndOne) {
  const auto clear = test::make_bsdf(masked_diffuse("<float name='opacity' value='0'/>"));
  const auto solid = test::make_bsdf(masked_diffuse("<float name='opacity' value='1'/>"));
  const auto plain = test::make_bsdf("<bsdf type='diffuse'><rgb name='reflectance' value='0.2, 0.5, 0.8'/></bsdf>");
  const Vec3 wo = direction(0.7f);
  for (int i = 0; i < 64; ++i) {
    const float u_lobe = (i + 0.5f) / 64;
    const Vec2 u{(i % 8 + 0.5f) / 8, (i / 8 + 0.5f) / 8};
    const auto c = clear->sample({}, wo, u_lobe, u);
    ASSERT_TRUE(c);
    EXPECT_TRUE(c->is_delta());
    EXPECT_EQ(c->wi, -wo);
    EXPECT_NEAR(c->f.g * std::abs(c->wi.z) / c->pdf, 1.0f, 1e-6f);
    const auto s = solid->sample({}, wo, u_lobe, u);
    const auto p = plain->sample({}, wo, u_lobe, u);
    ASSERT_TRUE(s && p);
    EXPECT_FALSE(s->is_delta());
    EXPECT_EQ(s->wi, p->wi);
    EXPECT_EQ(s->f, p->f);
    EXPECT_EQ(s->pdf, p->pdf);
  }
  EXPECT_EQ(clear->eval({}, wo, direction(0.2f)), Color());
  EXPECT_EQ(clear->pdf({}, wo, direction(0.2f)), 0.0f);
  EXPECT_EQ(solid->eval({}, wo, direction(0.2f)), plain->eval({}, wo, direction(0.2f)));
  // Even u_lobe just below 1 stays with the nested bsdf at opacity 1.
  EXPECT_FALSE(solid->sample({}, wo, 0x1.fffffep-1f, {0.5f, 0.5f})->is_delta());
}

TEST(MaskBsdf, TexturedOpacity) {
  const auto bsdf = test::make_bsdf(masked_diffuse(
      "<texture type='checkerboard' name='opacity'><float name='color0' value='1'/><float name='color1' value='0'/>"
      "</texture>"));
  const Vec3 wo = direction(0.5f), wi = direction(0.9f, 1.0f);
  EXPECT_GT(bsdf->eval({TransportMode::Radiance, {0.25f, 0.25f}}, wo, wi).r, 0.0f);
  EXPECT_EQ(bsdf->eval({TransportMode::Radiance, {0.75f, 0.25f}}, wo, wi), Color());
  EXPECT_TRUE(bsdf->sample({TransportMode::Radiance, {0.75f, 0.25f}}, wo, 0.01f, {0.5f, 0.5f})->is_delta());
}

TEST(MaskBsdf, NeedsOneNestedBsdf) {
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><shape type='rectangle'><bsdf type='mask'/></shape></scene>"),
              testing::HasSubstr("nested bsdf"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
