// blendbsdf against its parts: the mixture's eval, pdf and albedo are the
// parts' weighed by (1 - weight, weight), written out here from the parts
// made on their own; its sampling is checked by chi-square, sample/eval
// agreement, reciprocity and the white furnace like every material.

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

// Chi-square tests in this file: 3 incident angles x 2 weights (counted in kMaterialChi2Tests).
const double kAlpha = test::material_chi2_alpha();

const std::string kDiffuse = "<bsdf type='diffuse'><rgb name='reflectance' value='0.2, 0.5, 0.8'/></bsdf>";
const std::string kRough = "<bsdf type='roughconductor'><float name='alpha' value='0.2'/></bsdf>";

std::string blend(const std::string& weight, const std::string& first, const std::string& second) {
  return "<bsdf type='blendbsdf'>" + weight + first + second + "</bsdf>";
}

std::string weight(float w) { return "<float name='weight' value='" + std::to_string(w) + "'/>"; }

TEST(BlendBsdf, IsTheWeighedSumOfItsParts) {
  const auto diffuse = test::make_bsdf(kDiffuse), rough = test::make_bsdf(kRough);
  for (float w : {0.3f, 0.8f}) {
    const auto bsdf = test::make_bsdf(blend(weight(w), kDiffuse, kRough));
    EXPECT_EQ(bsdf->lobes(), uint32_t(kDiffuseReflection | kGlossyReflection));
    for (float theta : {0.0f, 0.8f, 1.5f}) {
      const BsdfContext ctx{};
      const Vec3 wo = direction(theta);
      const auto chi2 = test::chi2_bsdf(*bsdf, wo, ctx, {.sample_count = 200000, .bins_u = 20, .bins_v = 40});
      EXPECT_GT(chi2.p_value, kAlpha) << "weight " << w << " theta " << theta << "\n" << chi2.report;
      const auto c = test::check_samples(*bsdf, wo, ctx, 4000);
      EXPECT_GT(c.checked, 3900);
      EXPECT_LT(c.max_f_error, 1e-5);
      EXPECT_LT(c.max_pdf_error, 1e-5);
      EXPECT_EQ(c.non_finite, 0);
      EXPECT_NEAR(test::pdf_integral(*bsdf, wo, ctx),
                  (1 - w) * test::pdf_integral(*diffuse, wo, ctx) + w * test::pdf_integral(*rough, wo, ctx), 1e-3);
      for (const Vec3 wi : {direction(0.5f, 2.0f), direction(theta, 0.3f + kPi)}) {
        const Color want = diffuse->eval(ctx, wo, wi) * (1 - w) + rough->eval(ctx, wo, wi) * w;
        for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(bsdf->eval(ctx, wo, wi)[ch], want[ch], 1e-5f * (1 + want[ch]));
        EXPECT_NEAR(bsdf->pdf(ctx, wo, wi), (1 - w) * diffuse->pdf(ctx, wo, wi) + w * rough->pdf(ctx, wo, wi),
                    1e-5f * (1 + bsdf->pdf(ctx, wo, wi)));
      }
    }
    EXPECT_LT(test::reciprocity_error(*bsdf, {}, 2000), 1e-4);
  }
}

// A white diffuse surface blended with smooth glass (which reflects or
// transmits all it receives; in importance mode, where radiance's 1 / eta^2
// on refraction does not apply) loses nothing: the furnace stays at one,
// the glass's delta lobes sampled with their share.
TEST(BlendBsdf, WhiteFurnaceWithADeltaPart) {
  const auto bsdf = test::make_bsdf(blend(
      weight(0.4f), "<bsdf type='diffuse'><rgb name='reflectance' value='1'/></bsdf>", "<bsdf type='dielectric'/>"));
  EXPECT_EQ(bsdf->lobes(), uint32_t(kDiffuseReflection | kDeltaReflection | kDeltaTransmission));
  for (float theta : {0.1f, 1.0f, 1.55f}) {
    const auto a = test::albedo(*bsdf, direction(theta), test::kImportance, 100000);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a.mean[c], 1, 5 * a.standard_error[c] + 1e-5f) << theta;
    // Stratified u_lobe: the glass gets 400 of 1000 samples, and reflects
    // as many of them as its Fresnel reflectance says (unpolarised, bk7 in
    // air as Mitsuba's defaults, 1.5046 / 1.000277).
    int delta = 0, reflected = 0;
    for (int i = 0; i < 1000; ++i) {
      const auto s = bsdf->sample({}, direction(theta), (i + 0.5f) / 1000, {0.3f, 0.7f});
      ASSERT_TRUE(s);
      delta += s->is_delta();
      reflected += s->lobe == kDeltaReflection;
    }
    EXPECT_EQ(delta, 400);
    const double eta = 1.5046 / 1.000277, cos_i = std::cos(theta);
    const double cos_t = std::sqrt(1 - (1 - cos_i * cos_i) / (eta * eta));
    const double rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t), rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    EXPECT_NEAR(reflected, 400 * (rs * rs + rp * rp) / 2, 1.0) << theta;
  }
}

TEST(BlendBsdf, WeightZeroAndOneAreThePartsAlone) {
  const auto first = test::make_bsdf(blend(weight(0), kDiffuse, kRough));
  const auto second = test::make_bsdf(blend(weight(1), kDiffuse, kRough));
  const auto diffuse = test::make_bsdf(kDiffuse), rough = test::make_bsdf(kRough);
  const Vec3 wo = direction(0.7f), wi = direction(0.4f, 3.0f);
  EXPECT_EQ(first->eval({}, wo, wi), diffuse->eval({}, wo, wi));
  EXPECT_EQ(second->eval({}, wo, wi), rough->eval({}, wo, wi));
  for (const float u_lobe : {0.0f, 0.5f, 0x1.fffffep-1f}) {
    const auto a = first->sample({}, wo, u_lobe, {0.2f, 0.6f}), b = diffuse->sample({}, wo, u_lobe, {0.2f, 0.6f});
    ASSERT_TRUE(a && b);
    EXPECT_EQ(a->wi, b->wi);
    const auto c = second->sample({}, wo, u_lobe, {0.2f, 0.6f}), d = rough->sample({}, wo, u_lobe, {0.2f, 0.6f});
    ASSERT_TRUE(c && d);
    EXPECT_EQ(c->wi, d->wi);
  }
}

TEST(BlendBsdf, TexturedWeight) {
  const auto bsdf = test::make_bsdf(
      blend("<texture type='checkerboard' name='weight'><float name='color0' value='0'/><float name='color1' "
            "value='1'/></texture>",
            kDiffuse, kRough));
  const auto diffuse = test::make_bsdf(kDiffuse), rough = test::make_bsdf(kRough);
  const Vec3 wo = direction(0.5f), wi = direction(0.9f, 1.0f);
  EXPECT_EQ(bsdf->eval({TransportMode::Radiance, {0.25f, 0.25f}}, wo, wi), diffuse->eval({}, wo, wi));
  EXPECT_EQ(bsdf->eval({TransportMode::Radiance, {0.75f, 0.25f}}, wo, wi), rough->eval({}, wo, wi));
}

TEST(BlendBsdf, BadInput) {
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><shape type='rectangle'><bsdf type='blendbsdf'>" + kDiffuse +
                               "</bsdf></shape></scene>"),
              testing::HasSubstr("bsdf 'blendbsdf' takes two nested bsdfs, not 1"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><shape type='rectangle'>" +
                               blend(weight(1.5f), kDiffuse, kRough) + "</shape></scene>"),
              testing::HasSubstr("weight"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
