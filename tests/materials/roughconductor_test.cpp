#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tests/support/bsdf_checks.h"
#include "tests/support/chi2.h"
#include "tests/support/microfacet_oracle.h"
#include "tests/support/test_scenes.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using test::direction;

struct Case {
  const char* distribution;
  float alpha_u, alpha_v;
  bool sample_visible = true;
};

std::string element(const Case& c, const std::string& material = "<string name='material' value='Cu'/>") {
  const std::string roughness = c.alpha_u == c.alpha_v
                                    ? "<float name='alpha' value='" + std::to_string(c.alpha_u) + "'/>"
                                    : "<float name='alpha_u' value='" + std::to_string(c.alpha_u) +
                                          "'/><float name='alpha_v' value='" + std::to_string(c.alpha_v) + "'/>";
  return "<bsdf type='roughconductor'><string name='distribution' value='" + std::string(c.distribution) + "'/>" +
         roughness + material + "<boolean name='sample_visible' value='" + (c.sample_visible ? "true" : "false") +
         "'/></bsdf>";
}

const Case kCases[] = {
    {"beckmann", 0.05f, 0.05f},
    {"beckmann", 0.3f, 0.3f},
    {"beckmann", 1.0f, 1.0f},
    {"beckmann", 0.05f, 0.3f},
    {"ggx", 0.05f, 0.05f},
    {"ggx", 0.3f, 0.3f},
    {"ggx", 1.0f, 1.0f},
    {"ggx", 0.3f, 0.05f},
    {"beckmann", 0.3f, 0.3f, false},
    {"ggx", 0.3f, 0.3f, false},
    {"beckmann", 0.05f, 0.3f, false},
};
const float kThetas[] = {0.0f, 0.7f, 1.2f, 1.5607f};  // down to 0.01 rad from grazing
// Chi-square tests in this file: every case at every angle (counted in kMaterialChi2Tests).
const double kAlpha = test::material_chi2_alpha();

class RoughConductor : public testing::TestWithParam<Case> {};

TEST_P(RoughConductor, SamplesFollowThePdf) {
  const auto bsdf = test::make_bsdf(element(GetParam()));
  for (float theta : kThetas) {
    const Vec3 wo = direction(theta);
    // Bins fine enough that the quadrature of the expected counts resolves
    // the narrow lobes of alpha = 0.05: along cos(theta) around the normal,
    // along phi at the horizon.
    const int bins_phi = theta > 1.5f ? 80 : 40;
    const auto chi2 = test::chi2_bsdf(*bsdf, wo, {}, {.sample_count = 150000, .bins_u = 80, .bins_v = bins_phi});
    EXPECT_GT(chi2.p_value, kAlpha) << "theta " << theta << "\n" << chi2.report;
  }
}

TEST_P(RoughConductor, SamplesAgreeWithEvalAndPdf) {
  const auto bsdf = test::make_bsdf(element(GetParam()));
  for (float theta : kThetas) {
    const Vec3 wo = direction(theta);
    const auto c = test::check_samples(*bsdf, wo, {}, 2000);
    EXPECT_GT(c.checked, theta < 1.5f ? 800 : 100) << theta;
    EXPECT_LT(c.max_f_error, 1e-5) << theta;
    EXPECT_LT(c.max_pdf_error, 1e-5) << theta;
    EXPECT_EQ(c.non_finite, 0) << theta;
    EXPECT_LE(test::pdf_integral(*bsdf, wo, {}), 1.0 + 2e-3) << theta;
  }
}

// With a perfect mirror's Fresnel the white furnace loses only what single
// scattering leaves out: at most 1, close to 1 for smooth surfaces.
TEST_P(RoughConductor, WhiteFurnace) {
  const Case c = GetParam();
  const auto white = test::make_bsdf(element(c, ""));
  for (float theta : kThetas) {
    const Vec3 wo = direction(theta);
    const auto a = test::albedo(*white, wo, {}, 20000);
    EXPECT_LE(a.mean.r, 1.0f + 4 * a.standard_error.r + 1e-5f) << theta;
    EXPECT_GT(a.mean.r, c.alpha_u <= 0.05f && c.alpha_v <= 0.05f && theta < 1.5f ? 0.97f : 0.3f) << theta;
    EXPECT_LE(white->albedo({}, wo).max_component(), 1.0f);
    EXPECT_GE(white->albedo({}, wo).r, 0.0f);
  }
}

TEST_P(RoughConductor, Reciprocity) {
  const auto bsdf = test::make_bsdf(element(GetParam()));
  EXPECT_LT(test::reciprocity_error(*bsdf, {}, 2000), 1e-4);
}

INSTANTIATE_TEST_SUITE_P(Cases, RoughConductor, testing::ValuesIn(kCases));

// Nearly smooth: a narrow lobe around the mirror direction, still finite;
// alpha 0 reflects everything below grazing. At alpha 1e-3 and 1 the
// furnace equals the albedo integrated over microfacet normals in the test
// (tests/support/microfacet_oracle), grazing angles included, where
// masking takes a large share (z-test at 1 %, Sidak-corrected over the 16
// cases, plus the quadrature's error).
TEST(RoughConductorBsdf, ExtremeRoughness) {
  const double kZ = test::two_sided_z_critical(test::sidak_alpha(0.01, 16));
  for (const char* distribution : {"beckmann", "ggx"})
    for (float alpha : {1e-3f, 0.0f, 1.0f})
      for (float theta : {0.0f, 0.7f, 1.5607f, 1.5707f}) {
        const auto bsdf = test::make_bsdf(element({distribution, alpha, alpha}, ""));
        const Vec3 wo = direction(theta);
        const auto c = test::check_samples(*bsdf, wo, {}, 2000);
        EXPECT_EQ(c.non_finite, 0) << distribution << " " << alpha << " " << theta;
        EXPECT_LT(c.max_f_error, 1e-4) << distribution << " " << alpha << " " << theta;
        EXPECT_LT(c.max_pdf_error, 1e-4) << distribution << " " << alpha << " " << theta;
        const auto a = test::albedo(*bsdf, wo, {}, 2000);
        EXPECT_TRUE(a.mean.is_finite());
        EXPECT_LE(a.mean.r, 1.0f + 4 * a.standard_error.r + 1e-4f);
        if (alpha == 0 && theta < 1.5f) {
          EXPECT_NEAR(a.mean.r, 1.0f, 1e-3f) << distribution << " " << theta;
        }
        if (alpha > 0) {
          const test::MicrofacetModel m{std::string(distribution) == "ggx", alpha, alpha};
          const double expected = test::microfacet_albedo(m, {}, wo, 300).importance();
          const double error = std::abs(expected - test::microfacet_albedo(m, {}, wo, 150).importance()) + 1e-4;
          EXPECT_NEAR(a.mean.r, expected, kZ * a.standard_error.r + error)
              << distribution << " " << alpha << " theta " << theta << ": quadrature error " << error;
        }
        test::UniformSource u(9);
        for (int i = 0; i < 200; ++i) {
          const Vec3 wi = direction(std::acos(u.next_1d()), 6.2831853f * u.next_1d());
          EXPECT_TRUE(bsdf->eval({}, wo, wi).is_finite());
          EXPECT_TRUE(std::isfinite(bsdf->pdf({}, wo, wi)));
        }
        if (alpha <= 1e-3f && theta < 1.5f) {
          const auto s = bsdf->sample({}, wo, 0.5f, {0.3f, 0.6f});
          ASSERT_TRUE(s);
          EXPECT_NEAR(s->wi.z, wo.z, 0.02f);  // close to the mirror direction
        }
      }
}

// One-sided, and only reflection.
TEST(RoughConductorBsdf, BelowTheSurface) {
  const auto bsdf = test::make_bsdf("<bsdf type='roughconductor'><float name='alpha' value='0.3'/></bsdf>");
  EXPECT_EQ(bsdf->lobes(), uint32_t(kGlossyReflection));
  const Vec3 up = direction(0.5f), down(0.1f, 0.2f, -0.97467943f);
  EXPECT_EQ(bsdf->eval({}, up, down), Color());
  EXPECT_EQ(bsdf->eval({}, down, up), Color());
  EXPECT_EQ(bsdf->pdf({}, up, down), 0.0f);
  EXPECT_EQ(bsdf->pdf({}, down, up), 0.0f);
  EXPECT_FALSE(bsdf->sample({}, down, 0.5f, {0.5f, 0.5f}));
  EXPECT_FALSE(bsdf->sample({}, Vec3(1, 0, 0), 0.5f, {0.5f, 0.5f}));
  EXPECT_EQ(bsdf->albedo({}, down), Color());
  // Opposite grazing directions have no half vector.
  EXPECT_TRUE(bsdf->eval({}, Vec3(1, 0, 1e-8f), Vec3(-1, 0, 1e-8f)).is_finite());
  EXPECT_TRUE(std::isfinite(bsdf->pdf({}, Vec3(1, 0, 1e-8f), Vec3(-1, 0, 1e-8f))));
}

// Fresnel of the metal at the microfacet: at normal incidence with alpha
// small, the furnace gives ((eta-1)^2 + k^2) / ((eta+1)^2 + k^2) of copper.
TEST(RoughConductorBsdf, MetalFresnel) {
  const auto bsdf = test::make_bsdf(element({"ggx", 1e-3f, 1e-3f}));
  const auto a = test::albedo(*bsdf, Vec3(0, 0, 1), {}, 2000);
  const float eta[3] = {0.200f, 0.924f, 1.102f}, k[3] = {3.912f, 2.452f, 2.142f};
  for (int c = 0; c < 3; ++c) {
    const float expected = ((eta[c] - 1) * (eta[c] - 1) + k[c] * k[c]) / ((eta[c] + 1) * (eta[c] + 1) + k[c] * k[c]);
    EXPECT_NEAR(a.mean[c], expected, 2e-3f) << c;
    EXPECT_NEAR(bsdf->albedo({}, Vec3(0, 0, 1))[c], expected, 1e-5f) << c;
  }
}

TEST(RoughConductorBsdf, Defaults) {
  // Beckmann, alpha 0.1, a perfect mirror: a lobe around the mirror direction.
  const auto bsdf = test::make_bsdf("<bsdf type='roughconductor'/>");
  const auto same = test::make_bsdf(element({"beckmann", 0.1f, 0.1f}, ""));
  test::UniformSource u(4);
  for (int i = 0; i < 100; ++i) {
    const Vec3 wo = direction(std::acos(u.next_1d()), 6.2831853f * u.next_1d());
    const Vec3 wi = direction(std::acos(u.next_1d()), 6.2831853f * u.next_1d());
    EXPECT_EQ(bsdf->eval({}, wo, wi), same->eval({}, wo, wi));
    EXPECT_EQ(bsdf->pdf({}, wo, wi), same->pdf({}, wo, wi));
  }
}

TEST(RoughConductorBsdf, BadInput) {
  const auto scene = [](const std::string& bsdf) {
    return "<scene version='3.0.0'><shape type='rectangle'>\n" + bsdf + "\n</shape></scene>";
  };
  const auto expect_error = [&](const std::string& bsdf, const std::string& part) {
    const std::string message = test::load_error(scene(bsdf));
    EXPECT_NE(message.find("test.xml:2"), std::string::npos) << message;
    EXPECT_NE(message.find(part), std::string::npos) << message;
  };
  expect_error("<bsdf type='roughconductor'><string name='distribution' value='phong'/></bsdf>", "beckmann or ggx");
  expect_error("<bsdf type='roughconductor'><string name='material' value='Zz'/></bsdf>", "unknown conductor 'Zz'");
  expect_error("<bsdf type='roughconductor'><float name='alpha' value='-0.1'/></bsdf>", "not negative");
  expect_error("<bsdf type='roughconductor'><float name='alpha_u' value='0.1'/></bsdf>", "go together");
  expect_error(
      "<bsdf type='roughconductor'><float name='alpha' value='0.1'/><float name='alpha_u' value='0.1'/>"
      "<float name='alpha_v' value='0.1'/></bsdf>",
      "not both");
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
