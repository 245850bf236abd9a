#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/bsdf/fresnel.h"
#include "core/math/constants.h"
#include "tests/support/bsdf_checks.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using test::direction;

const float kThetas[] = {0.0f, 0.7f, 1.4f, 1.5607f};  // down to 0.01 rad from grazing

struct Config {
  std::string xml;
  float eta;  // int_ior / ext_ior
  float kd_mean, ks_mean;
};

// polypropylene 1.49, air 1.000277, bk7 1.5046.
const Config kConfigs[] = {
    {"<bsdf type='plastic'/>", 1.49f / 1.000277f, 0.5f, 1.0f},
    {"<bsdf type='plastic'><rgb name='diffuse_reflectance' value='0.1, 0.5, 0.9'/>"
     "<rgb name='specular_reflectance' value='0.3'/><boolean name='nonlinear' value='true'/></bsdf>",
     1.49f / 1.000277f, 0.5f, 0.3f},
    {"<bsdf type='plastic'><float name='int_ior' value='1.9'/><string name='ext_ior' value='bk7'/></bsdf>",
     1.9f / 1.5046f, 0.5f, 1.0f},
};

// Chi-square tests in this file: 3 materials x 4 incident angles (counted in kMaterialChi2Tests).
const double kAlpha = test::material_chi2_alpha();

float specular_probability(const Config& c, Vec3 wo) {
  const float F = fresnel_dielectric(wo.z, c.eta).F;
  return F * c.ks_mean / (F * c.ks_mean + (1 - F) * c.kd_mean);
}

TEST(PlasticBsdf, SamplesFollowThePdf) {
  for (const Config& config : kConfigs) {
    const auto bsdf = test::make_bsdf(config.xml);
    for (float theta : kThetas) {
      const Vec3 wo = direction(theta);
      const auto chi2 = test::chi2_bsdf(*bsdf, wo, {}, {.sample_count = 200000, .bins_u = 20, .bins_v = 40});
      EXPECT_GT(chi2.p_value, kAlpha) << config.xml << " theta " << theta << "\n" << chi2.report;
      const auto c = test::check_samples(*bsdf, wo, {}, 2000);
      EXPECT_GT(c.checked, 20);  // near grazing nearly all samples are mirror ones
      EXPECT_LT(c.max_f_error, 1e-6);
      EXPECT_LT(c.max_pdf_error, 1e-6);
      EXPECT_EQ(c.non_finite, 0);
      // The delta lobe takes the rest.
      EXPECT_NEAR(test::pdf_integral(*bsdf, wo, {}), 1 - specular_probability(config, wo), 1e-3)
          << config.xml << " theta " << theta;
    }
  }
}

TEST(PlasticBsdf, DeltaLobeIsTheFresnelMirror) {
  const Config& config = kConfigs[1];
  const auto bsdf = test::make_bsdf(config.xml);
  const Vec3 wo = direction(1.0f);
  const float p = specular_probability(config, wo);
  const auto s = bsdf->sample({}, wo, p * 0.5f, {0.3f, 0.7f});
  ASSERT_TRUE(s);
  EXPECT_TRUE(s->is_delta());
  EXPECT_EQ(s->lobe, kDeltaReflection);
  EXPECT_NEAR(s->pdf, p, 1e-6f);
  EXPECT_NEAR(s->wi.x, -wo.x, 1e-7f);
  EXPECT_NEAR(s->wi.y, -wo.y, 1e-7f);
  EXPECT_NEAR(s->wi.z, wo.z, 1e-7f);
  EXPECT_NEAR(s->f.g * s->wi.z, 0.3f * fresnel_dielectric(wo.z, config.eta).F, 1e-6f);
  EXPECT_EQ(bsdf->eval({}, wo, s->wi), bsdf->eval({}, wo, direction(1.0f, 2.0f)));  // no delta in eval
  const auto d = bsdf->sample({}, wo, p + (1 - p) * 0.5f, {0.3f, 0.7f});
  ASSERT_TRUE(d);
  EXPECT_EQ(d->lobe, kDiffuseReflection);
}

TEST(PlasticBsdf, WhiteFurnaceAndReciprocity) {
  // White base and coating: no absorption, so exactly all light comes back,
  // for both forms (this also checks the numerical F_dr).
  for (const char* nonlinear : {"false", "true"})
    for (const char* ior : {"1.49", "1.9", "1.1"}) {
      const auto white = test::make_bsdf(
          std::string("<bsdf type='plastic'><rgb name='diffuse_reflectance' value='1'/>") +
          "<float name='int_ior' value='" + ior + "'/><boolean name='nonlinear' value='" + nonlinear + "'/></bsdf>");
      for (float theta : kThetas) {
        const Vec3 wo = direction(theta);
        const auto a = test::albedo(*white, wo, {}, 100000);
        EXPECT_LE(a.mean.r, 1.0f + 4 * a.standard_error.r + 1e-4f) << ior << " theta " << theta;
        EXPECT_NEAR(a.mean.r, 1.0f, 4 * a.standard_error.r + 1e-3f) << ior << " theta " << theta;
        EXPECT_NEAR(white->albedo({}, wo).r, 1.0f, 1e-3f);
      }
      EXPECT_LT(test::reciprocity_error(*white, {}, 1000), 1e-5);
    }
  // A coloured, nonlinear material: albedo() matches the sampled estimate.
  const auto coloured = test::make_bsdf(kConfigs[1].xml);
  for (float theta : kThetas) {
    const Vec3 wo = direction(theta);
    const auto a = test::albedo(*coloured, wo, {}, 100000);
    const Color reported = coloured->albedo({}, wo);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(reported[c], a.mean[c], 4 * a.standard_error[c] + 1e-3f) << "theta " << theta << " channel " << c;
      EXPECT_LE(reported[c], 1.0f);
    }
  }
  EXPECT_LT(test::reciprocity_error(*coloured, {}, 1000), 1e-5);
  EXPECT_EQ(coloured->eval({}, direction(0.3f), Vec3(0, 0, -1)), Color());  // no transmission
  EXPECT_EQ(coloured->eval({}, Vec3(0, 0, -1), direction(0.3f)), Color());  // one-sided
  EXPECT_FALSE(coloured->sample({}, Vec3(0, 0, -1), 0.5f, {0.5f, 0.5f}));
}

TEST(PlasticBsdf, HardCasesStayFinite) {
  const std::string cases[] = {
      "<bsdf type='plastic'><float name='int_ior' value='1.000277'/></bsdf>",  // no coating at all
      "<bsdf type='plastic'><float name='int_ior' value='10'/><boolean name='nonlinear' value='true'/>"
      "<rgb name='diffuse_reflectance' value='1'/></bsdf>",
      "<bsdf type='plastic'><float name='int_ior' value='1.2'/><float name='ext_ior' value='1.5'/></bsdf>",
      "<bsdf type='plastic'><rgb name='diffuse_reflectance' value='0'/></bsdf>",
      "<bsdf type='plastic'><rgb name='specular_reflectance' value='0'/></bsdf>",
      "<bsdf type='plastic'><rgb name='diffuse_reflectance' value='0'/><rgb name='specular_reflectance' "
      "value='0'/></bsdf>",
  };
  for (const std::string& xml : cases) {
    const auto bsdf = test::make_bsdf(xml);
    for (float theta : {0.0f, 1.5607f, 1.5707f}) {
      const Vec3 wo = direction(theta);
      const auto c = test::check_samples(*bsdf, wo, {}, 2000);
      EXPECT_EQ(c.non_finite, 0) << xml;
      EXPECT_LT(c.max_f_error, 1e-6) << xml;
      const auto a = test::albedo(*bsdf, wo, {}, 20000);
      EXPECT_TRUE(a.mean.is_finite()) << xml;
      EXPECT_LE(a.mean.max_component(), 1.0f + 4 * a.standard_error.max_component() + 1e-3f) << xml;
      EXPECT_TRUE(bsdf->albedo({}, wo).is_finite()) << xml;
      EXPECT_TRUE(bsdf->eval({}, wo, direction(0.4f)).is_finite()) << xml;
      EXPECT_TRUE(std::isfinite(bsdf->pdf({}, wo, direction(0.4f)))) << xml;
    }
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
