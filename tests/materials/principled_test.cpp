#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "core/math/constants.h"
#include "tests/support/bsdf_checks.h"
#include "tests/support/burley_oracle.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using test::below;
using test::direction;
using test::kImportance;
using test::kRadiance;
using ::testing::HasSubstr;

// Chi-square tests in this file: 3 opaque materials x 3 directions and 2
// glassy ones x 5 (counted in kMaterialChi2Tests).
const double kAlpha = test::material_chi2_alpha();

struct Material {
  double base[3] = {0.5, 0.5, 0.5};
  double roughness = 0.5, anisotropic = 0, metallic = 0, spec_trans = 0, eta = 1.5, spec_tint = 0, sheen = 0,
         sheen_tint = 0, flatness = 0, clearcoat = 0, clearcoat_gloss = 0;

  std::string xml() const {
    const auto f = [](const char* name, double v) {
      return "<float name='" + std::string(name) + "' value='" + std::to_string(v) + "'/>";
    };
    return "<bsdf type='principled'><rgb name='base_color' value='" + std::to_string(base[0]) + ", " +
           std::to_string(base[1]) + ", " + std::to_string(base[2]) + "'/>" + f("roughness", roughness) +
           f("anisotropic", anisotropic) + f("metallic", metallic) + f("spec_trans", spec_trans) + f("eta", eta) +
           f("spec_tint", spec_tint) + f("sheen", sheen) + f("sheen_tint", sheen_tint) + f("flatness", flatness) +
           f("clearcoat", clearcoat) + f("clearcoat_gloss", clearcoat_gloss) + "</bsdf>";
  }
};

Material coloured_metal() {
  Material m;
  m.base[0] = 0.9, m.base[1] = 0.6, m.base[2] = 0.2;
  m.roughness = 0.35, m.anisotropic = 0.6, m.metallic = 1;
  return m;
}

Material everything_opaque() {
  Material m;
  m.base[0] = 0.8, m.base[1] = 0.3, m.base[2] = 0.2;
  m.roughness = 0.4, m.metallic = 0.3, m.spec_tint = 0.5, m.sheen = 1, m.sheen_tint = 0.5, m.flatness = 0.5;
  m.clearcoat = 1, m.clearcoat_gloss = 0.7, m.anisotropic = 0.3;
  return m;
}

Material glass() {
  Material m;
  m.base[0] = m.base[1] = m.base[2] = 1;
  m.roughness = 0.5, m.spec_trans = 1;
  return m;
}

Material half_glass() {
  Material m;
  m.base[0] = 0.7, m.base[1] = 0.9, m.base[2] = 0.4;
  m.roughness = 0.7, m.spec_trans = 0.5, m.metallic = 0.2, m.eta = 1.33, m.clearcoat = 0.5, m.sheen = 0.5;
  return m;
}

// The published model (tests/support/burley_oracle.h), wo above the surface.
using namespace test::burley;

double gtr1_D(double cos_h, double alpha) {
  const double a2 = alpha * alpha;
  return (a2 - 1) / (kPi * std::log(a2) * (1 + (a2 - 1) * cos_h * cos_h));
}

double clearcoat_visibility(double cos) {
  const double a2 = 0.25 * 0.25;
  return 1 / (cos + std::sqrt(a2 + cos * cos - a2 * cos * cos));
}

// f(wo, wi) per channel, wo above the surface; radiance transport.
std::array<double, 3> published(const Material& m, Dir v, Dir l) {
  std::array<double, 3> out{};
  const double brdf = (1 - m.metallic) * (1 - m.spec_trans), bsdf = (1 - m.metallic) * m.spec_trans;
  const double lum = 0.2126 * m.base[0] + 0.7152 * m.base[1] + 0.0722 * m.base[2];
  const Alphas a = alphas(m.roughness, m.anisotropic);
  if (l.z > 0) {
    const Dir h = unit({v.x + l.x, v.y + l.y, v.z + l.z});
    const double cos_d = dot3(l, h);
    const double lambert = diffuse(l.z, v.z, cos_d, m.roughness, m.flatness);
    const double fh = schlick(cos_d);
    const double F_d = fresnel(dot3(v, h), 1, m.eta);
    const double r0 = (m.eta - 1) * (m.eta - 1) / ((m.eta + 1) * (m.eta + 1));
    const double vis = ggx_visibility(v, a) * ggx_visibility(l, a);
    const double D = ggx_D(h, a);
    const double coat = 0.25 * m.clearcoat * (0.04 + 0.96 * fh) * gtr1_D(h.z, 0.1 + (0.001 - 0.1) * m.clearcoat_gloss) *
                        clearcoat_visibility(l.z) * clearcoat_visibility(v.z);
    for (int c = 0; c < 3; ++c) {
      const double tint = lum > 0 ? m.base[c] / lum : 1;
      const double metal = m.base[c] + (1 - m.base[c]) * fh;
      const double tinted = tint * r0 + (1 - tint * r0) * fh;
      const double F =
          (1 - m.metallic) * (1 - m.spec_tint) * F_d + m.metallic * metal + (1 - m.metallic) * m.spec_tint * tinted;
      const double sheen = m.sheen * (1 + m.sheen_tint * (tint - 1)) * fh;
      out[c] = brdf * (m.base[c] * lambert + sheen) + F * D * vis + coat;
    }
    return out;
  }
  // Transmission (Walter et al. 2007), into the index eta.
  Dir h = unit({-(v.x + m.eta * l.x), -(v.y + m.eta * l.y), -(v.z + m.eta * l.z)});
  if (h.z < 0) h = {-h.x, -h.y, -h.z};
  const double vh = dot3(v, h), lh = dot3(l, h);
  if (vh <= 0 || lh >= 0) return out;
  const double F_d = fresnel(vh, 1, m.eta);
  // G1 = 2 |cos| visibility.
  const double G = 4 * std::abs(v.z) * std::abs(l.z) * ggx_visibility(v, a) * ggx_visibility(l, a);
  const double t = std::abs(vh * lh) / (std::abs(v.z) * std::abs(l.z)) * (1 - F_d) * ggx_D(h, a) * G /
                   ((vh + m.eta * lh) * (vh + m.eta * lh));
  for (int c = 0; c < 3; ++c) out[c] = bsdf * std::sqrt(m.base[c]) * t;
  return out;
}

TEST(PrincipledBsdf, MatchesThePublishedModel) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0, 1);
  for (const Material& m : {Material{}, coloured_metal(), everything_opaque(), glass(), half_glass()}) {
    const auto bsdf = test::make_bsdf(m.xml());
    int compared = 0;
    for (int i = 0; i < 400; ++i) {
      const float theta_o = std::acos(u(rng)), theta_i = std::acos(2 * u(rng) - 1);
      const Vec3 wo = direction(theta_o, 2 * kPi * u(rng)), wi = direction(theta_i, 2 * kPi * u(rng));
      if (wo.z < 0.02f || std::abs(wi.z) < 0.02f) continue;
      const auto expected = published(m, {wo.x, wo.y, wo.z}, {wi.x, wi.y, wi.z});
      const Color f = bsdf->eval(kRadiance, wo, wi);
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(f[c], expected[c], 2e-3 * expected[c] + 1e-6)
            << m.xml() << "\nwo " << wo.x << " " << wo.y << " " << wo.z << " wi " << wi.x << " " << wi.y << " " << wi.z
            << " channel " << c;
      compared += expected[0] > 0;
    }
    EXPECT_GT(compared, 100) << m.xml();
  }
}

TEST(PrincipledBsdf, SamplesFollowThePdf) {
  const auto check = [](const Material& m, Vec3 wo) {
    const auto bsdf = test::make_bsdf(m.xml());
    const auto chi2 = test::chi2_bsdf(*bsdf, wo, kRadiance, {.sample_count = 200000, .bins_u = 40, .bins_v = 80});
    EXPECT_GT(chi2.p_value, kAlpha) << m.xml() << " wo.z " << wo.z << "\n" << chi2.report;
    for (const BsdfContext& ctx : {kRadiance, kImportance}) {
      const auto c = test::check_samples(*bsdf, wo, ctx, 2000);
      EXPECT_GT(c.checked, 1000) << m.xml();
      EXPECT_LT(c.max_f_error, 1e-4) << m.xml();
      EXPECT_LT(c.max_pdf_error, 1e-4) << m.xml();
      EXPECT_EQ(c.non_finite, 0) << m.xml();
    }
    const double integral = test::pdf_integral(*bsdf, wo, kRadiance);
    EXPECT_LE(integral, 1 + 1e-3) << m.xml() << " wo.z " << wo.z;
    EXPECT_GT(integral, 0.5) << m.xml() << " wo.z " << wo.z;
  };
  for (const Material& m : {Material{}, coloured_metal(), everything_opaque()})
    for (float theta : {0.3f, 1.2f, 1.5607f}) check(m, direction(theta));
  for (const Material& m : {glass(), half_glass()})
    for (Vec3 wo :
         {direction(0.3f), direction(1.2f), direction(1.5607f), below(direction(0.4f)), below(direction(1.2f))})
      check(m, wo);
}

// Reflection is reciprocal; transmission is not (radiance is compressed on
// entering a denser medium) but obeys f(wo, wi) / eta_i^2 = f(wi, wo) / eta_o^2
// in importance transport, and the radiance form is the importance form
// times eta_o^2 / eta_i^2.
TEST(PrincipledBsdf, ReciprocityAndTheTwoTransportModes) {
  for (const Material& m : {Material{}, coloured_metal(), everything_opaque()})
    EXPECT_LT(test::reciprocity_error(*test::make_bsdf(m.xml()), kRadiance, 2000), 1e-4) << m.xml();
  const Material h = half_glass();
  const auto bsdf = test::make_bsdf(h.xml());
  const float eta = float(h.eta);
  // wo at 0.5 rad refracts to about 0.37 rad; rough facets spread it.
  for (float theta_i : {0.2f, 0.35f, 0.5f}) {
    const Vec3 wo = direction(0.5f, 0.4f), wi = below(direction(theta_i, 0.4f + kPi));
    const Color radiance = bsdf->eval(kRadiance, wo, wi), importance = bsdf->eval(kImportance, wo, wi);
    ASSERT_GT(radiance.g, 0);
    EXPECT_NEAR(radiance.g * eta * eta, importance.g, 1e-4f * importance.g);
    const Color back = bsdf->eval(kImportance, wi, wo);
    EXPECT_NEAR(importance.g / (eta * eta), back.g, 2e-4f * back.g);
  }
}

// A white metal reflects everything a single microfacet bounce can: at most
// 1 (4 standard errors), nearly all of it when smooth. Clear glass of
// roughness 1 (GGX alpha 1) loses more than half of the light to masking
// from inside at grazing angles, in a single bounce.
TEST(PrincipledBsdf, WhiteFurnace) {
  for (double roughness : {0.05, 0.5, 1.0}) {
    Material m;
    m.base[0] = m.base[1] = m.base[2] = 1;
    m.metallic = 1, m.roughness = roughness;
    const auto metal = test::make_bsdf(m.xml());
    Material g = glass();
    g.roughness = roughness;
    const auto clear = test::make_bsdf(g.xml());
    for (float theta : {0.0f, 0.8f, 1.4f}) {
      const auto a = test::albedo(*metal, direction(theta), kRadiance, 40000);
      EXPECT_LE(a.mean.g, 1 + 4 * a.standard_error.g) << roughness << " " << theta;
      if (roughness < 0.1) {
        EXPECT_GT(a.mean.g, 0.98f) << roughness << " " << theta;
      }
      // Clear glass reflects and transmits (importance carries no eta^2).
      for (Vec3 wo : {direction(theta), below(direction(theta))}) {
        const auto t = test::albedo(*clear, wo, kImportance, 40000);
        EXPECT_LE(t.mean.g, 1 + 4 * t.standard_error.g) << roughness << " " << theta << " " << wo.z;
        EXPECT_GT(t.mean.g, roughness < 0.1 ? 0.97f : 0.2f) << roughness << " " << theta << " " << wo.z;
      }
    }
  }
}

TEST(PrincipledBsdf, OpaqueMaterialsSendNothingThroughOrFromBelow) {
  for (const Material& m : {Material{}, coloured_metal(), everything_opaque()}) {
    const auto bsdf = test::make_bsdf(m.xml());
    EXPECT_EQ(bsdf->eval(kRadiance, direction(0.3f), below(direction(0.5f))), Color()) << m.xml();
    EXPECT_EQ(bsdf->eval(kRadiance, below(direction(0.3f)), direction(0.5f)), Color()) << m.xml();
    EXPECT_FALSE(bsdf->sample(kRadiance, below(direction(0.3f)), 0.5f, {0.5f, 0.5f})) << m.xml();
    EXPECT_FALSE(bsdf->lobes() & kTransmission);
  }
  EXPECT_TRUE(test::make_bsdf(glass().xml())->lobes() & kGlossyTransmission);
}

// The defaults are Mitsuba's: specular 0.5 is eta 1.5 (R0 = 0.04), grey
// base 0.5, roughness 0.5.
TEST(PrincipledBsdf, SpecularAndEtaAreOneParameter) {
  const auto by_specular = test::make_bsdf("<bsdf type='principled'/>");
  const auto by_eta = test::make_bsdf("<bsdf type='principled'><float name='eta' value='1.5'/></bsdf>");
  for (float theta : {0.2f, 1.0f}) {
    const Vec3 wo = direction(theta), wi = direction(0.7f, 2.0f);
    const Color a = by_specular->eval(kRadiance, wo, wi), b = by_eta->eval(kRadiance, wo, wi);
    EXPECT_NEAR(a.g, b.g, 1e-5f * b.g);
  }
  Material m;
  EXPECT_NEAR(by_specular->eval(kRadiance, direction(0.4f), direction(0.9f, 2.0f)).g,
              published(m, {direction(0.4f).x, direction(0.4f).y, direction(0.4f).z},
                        {direction(0.9f, 2.0f).x, direction(0.9f, 2.0f).y, direction(0.9f, 2.0f).z})[1],
              1e-5);
}

TEST(PrincipledBsdf, HardCasesStayFinite) {
  for (Material m : {Material{}, coloured_metal(), everything_opaque(), glass(), half_glass()})
    for (double roughness : {0.0, 1.0}) {
      m.roughness = roughness;
      const auto bsdf = test::make_bsdf(m.xml());
      for (Vec3 wo : {direction(0.0f), direction(1.5707f), below(direction(1.5707f)), below(direction(0.0f))})
        for (const BsdfContext& ctx : {kRadiance, kImportance}) {
          const auto c = test::check_samples(*bsdf, wo, ctx, 1000);
          EXPECT_EQ(c.non_finite, 0) << m.xml() << " wo.z " << wo.z;
          EXPECT_TRUE(bsdf->albedo(ctx, wo).is_finite());
          for (float u_lobe : {0.0f, 0.5f, kOneMinusEpsilon})
            for (Vec2 u : {Vec2{0, 0}, Vec2{kOneMinusEpsilon, kOneMinusEpsilon}})
              if (const auto s = bsdf->sample(ctx, wo, u_lobe, u)) {
                EXPECT_TRUE(s->f.is_finite() && std::isfinite(s->pdf)) << m.xml();
                EXPECT_GT(s->pdf, 0);
              }
        }
    }
}

TEST(PrincipledBsdf, BadParametersNameThemselves) {
  const auto error = [](const std::string& inner) {
    return test::load_error("<scene version='3.0.0'>\n<bsdf type='principled'>\n" + inner + "</bsdf></scene>",
                            "bad.xml");
  };
  EXPECT_THAT(error("<float name='eta' value='1.4'/><float name='specular' value='0.3'/>"),
              HasSubstr("bad.xml:3: parameter 'specular' of bsdf 'principled': give either eta or specular, not "
                        "both (each sets the other)"));
  EXPECT_THAT(error("<float name='eta' value='0'/>"), HasSubstr("parameter 'eta' of bsdf 'principled': must be "
                                                                "positive"));
  EXPECT_THAT(error("<float name='specular' value='13'/>"),
              HasSubstr("parameter 'specular' of bsdf 'principled': must lie in [0, 12.5)"));
  EXPECT_THAT(error("<float name='metallic' value='1.5'/>"),
              HasSubstr("parameter 'metallic' of bsdf 'principled': must lie in [0, 1]"));
  EXPECT_THAT(error("<float name='roughness' value='-0.1'/>"),
              HasSubstr("parameter 'roughness' of bsdf 'principled': must lie in [0, 1]"));
  EXPECT_THAT(error("<float name='clearcoat_sampling_rate' value='0'/>"),
              HasSubstr("parameter 'clearcoat_sampling_rate' of bsdf 'principled': must be positive"));
  EXPECT_THAT(error("<rgb name='base_color' value='0.5, -1, 0.5'/>"),
              HasSubstr("parameter 'base_color' of bsdf 'principled': must not be negative"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
