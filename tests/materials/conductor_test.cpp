#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "core/bsdf/conductor_data.h"
#include "core/bsdf/fresnel.h"
#include "tests/support/bsdf_checks.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using test::direction;
using ::testing::HasSubstr;

const float kThetas[] = {0.0f, 0.5f, 1.0f, 1.4f, 1.5607f};

// The mirror direction of wo.
Vec3 mirror(Vec3 wo) { return {-wo.x, -wo.y, wo.z}; }

TEST(ConductorBsdf, IsADeltaMirror) {
  const auto bsdf = test::make_bsdf("<bsdf type='conductor'><string name='material' value='Au'/></bsdf>");
  EXPECT_EQ(bsdf->lobes(), uint32_t(kDeltaReflection));
  test::UniformSource u(5);
  for (float theta : kThetas) {
    const Vec3 wo = direction(theta);
    const auto s = bsdf->sample({}, wo, u.next_1d(), u.next_2d());
    ASSERT_TRUE(s);
    EXPECT_TRUE(s->is_delta());
    EXPECT_EQ(s->lobe, uint32_t(kDeltaReflection));
    EXPECT_EQ(s->pdf, 1.0f);
    EXPECT_NEAR(length(s->wi - mirror(wo)), 0.0f, 1e-6f);
    EXPECT_TRUE(s->f.is_finite());
    // f |cos| is the Fresnel reflectance, which albedo() reports.
    const Color weighted = s->f * std::abs(s->wi.z), a = bsdf->albedo({}, wo);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(weighted[c], a[c], 1e-6f * std::max(1.0f, a[c]));
    // No density anywhere, not even in the mirror direction.
    EXPECT_EQ(bsdf->eval({}, wo, s->wi), Color());
    EXPECT_EQ(bsdf->pdf({}, wo, s->wi), 0.0f);
    const auto c = test::check_samples(*bsdf, wo, {}, 100);
    EXPECT_EQ(c.checked, 0);  // all delta
    EXPECT_EQ(c.non_finite, 0);
    EXPECT_EQ(test::pdf_integral(*bsdf, wo, {}), 0.0);
  }
}

// A perfect mirror by default: the white furnace returns everything at every
// angle, including grazing.
TEST(ConductorBsdf, DefaultIsAPerfectMirror) {
  const auto bsdf = test::make_bsdf("<bsdf type='conductor'/>");
  for (float theta : {0.0f, 0.3f, 0.8f, 1.2f, 1.5f, 1.5607f, 1.5707f}) {
    const Vec3 wo = direction(theta);
    const auto a = test::albedo(*bsdf, wo, {}, 100);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(a.mean[c], 1.0f, 1e-5f) << theta;
      EXPECT_EQ(bsdf->albedo({}, wo)[c], 1.0f) << theta;
    }
  }
}

// Measured metals reflect less than everything (with a shallow dip near the
// pseudo-Brewster angle), and everything at grazing incidence.
TEST(ConductorBsdf, MetalsStayBelowOne) {
  for (const auto& name : conductor_names()) {
    const auto bsdf = test::make_bsdf("<bsdf type='conductor'><string name='material' value='" + name + "'/></bsdf>");
    for (float theta : {0.0f, 0.5f, 1.0f, 1.3f, 1.5f, 1.5607f}) {
      const Color a = bsdf->albedo({}, direction(theta));
      const auto estimate = test::albedo(*bsdf, direction(theta), {}, 100);
      for (int c = 0; c < 3; ++c) {
        EXPECT_GT(a[c], 0.0f) << name;
        EXPECT_LE(a[c], 1.0f) << name;
        EXPECT_NEAR(estimate.mean[c], a[c], 1e-5f) << name;
      }
    }
    EXPECT_GT(bsdf->albedo({}, direction(1.5707f)).max_component(), 0.99f) << name;
  }
}

// At normal incidence F = ((eta - 1)^2 + k^2) / ((eta + 1)^2 + k^2).
TEST(ConductorBsdf, NormalIncidenceFresnel) {
  for (const auto& name : conductor_names()) {
    const auto ior = *named_conductor(name);
    const auto bsdf = test::make_bsdf("<bsdf type='conductor'><string name='material' value='" + name + "'/></bsdf>");
    const Color a = bsdf->albedo({}, Vec3(0, 0, 1));
    for (int c = 0; c < 3; ++c) {
      const double eta = ior.eta[c], k = ior.k[c];
      const double expected = ((eta - 1) * (eta - 1) + k * k) / ((eta + 1) * (eta + 1) + k * k);
      EXPECT_NEAR(a[c], expected, 1e-5) << name << " channel " << c;
    }
  }
  // Gold is yellow: red reflected most, blue least.
  const Color gold =
      test::make_bsdf("<bsdf type='conductor'><string name='material' value='Au'/></bsdf>")->albedo({}, Vec3(0, 0, 1));
  EXPECT_GT(gold.r, gold.g);
  EXPECT_GT(gold.g, gold.b);
}

TEST(ConductorBsdf, ExplicitIndexAndReflectance) {
  const auto bsdf = test::make_bsdf(
      "<bsdf type='conductor'><rgb name='eta' value='0.2, 0.9, 1.1'/><rgb name='k' value='3.9, 2.4, 2.1'/>"
      "<rgb name='specular_reflectance' value='0.5, 1, 0.25'/></bsdf>");
  const Vec3 wo = direction(0.7f);
  const Color expected =
      fresnel_conductor(wo.z, Color(0.2f, 0.9f, 1.1f), Color(3.9f, 2.4f, 2.1f)) * Color(0.5f, 1, 0.25f);
  const Color a = bsdf->albedo({}, wo);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], expected[c], 1e-6f);
  // A float index applies to every channel.
  const auto grey =
      test::make_bsdf("<bsdf type='conductor'><float name='eta' value='1.5'/><float name='k' value='2'/></bsdf>");
  const Color g = grey->albedo({}, Vec3(0, 0, 1));
  EXPECT_NEAR(g.r, (0.25f + 4) / (6.25f + 4), 1e-6f);
  EXPECT_EQ(g.r, g.b);
}

// One-sided: nothing scatters from below, and nothing is NaN.
TEST(ConductorBsdf, BelowAndDegenerate) {
  const auto bsdf = test::make_bsdf("<bsdf type='conductor'><string name='material' value='Cu'/></bsdf>");
  EXPECT_FALSE(bsdf->sample({}, Vec3(0, 0, -1), 0.5f, {0.5f, 0.5f}));
  EXPECT_FALSE(bsdf->sample({}, direction(2.0f), 0.5f, {0.5f, 0.5f}));
  EXPECT_FALSE(bsdf->sample({}, Vec3(1, 0, 0), 0.5f, {0.5f, 0.5f}));  // in the tangent plane
  EXPECT_EQ(bsdf->albedo({}, Vec3(0, 0, -1)), Color());
  const auto s = bsdf->sample({}, direction(1.5707f), 0.1f, {0.9f, 0.2f});
  ASSERT_TRUE(s);
  EXPECT_TRUE(s->f.is_finite());
  EXPECT_EQ(test::reciprocity_error(*bsdf, {}, 100), 0.0);
}

TEST(ConductorBsdf, BadInput) {
  const auto scene = [](const std::string& bsdf) {
    return "<scene version='3.0.0'><shape type='rectangle'>\n" + bsdf + "\n</shape></scene>";
  };
  const std::string unknown =
      test::load_error(scene("<bsdf type='conductor'><string name='material' value='Xx'/></bsdf>"));
  EXPECT_NE(unknown.find("test.xml:2"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("unknown conductor 'Xx'"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("Au"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("Cu"), std::string::npos) << unknown;
  const std::string both = test::load_error(
      scene("<bsdf type='conductor'><string name='material' value='Au'/><float name='eta' value='1'/></bsdf>"));
  EXPECT_NE(both.find("not both"), std::string::npos) << both;
  const std::string negative = test::load_error(scene("<bsdf type='conductor'><float name='k' value='-1'/></bsdf>"));
  EXPECT_NE(negative.find("negative"), std::string::npos) << negative;
  EXPECT_NE(negative.find("test.xml:2"), std::string::npos) << negative;
}

// Every material name Mitsuba 3's conductor accepts (its plugin reference)
// is accepted, or refused by a message saying it is Mitsuba's and why it is
// missing; 50 of the 65 have tables.
TEST(ConductorBsdf, EveryNameMitsubaAccepts) {
  const char* const names[] = {
      "a-C",        "Ag",       "Al",         "AlAs",     "AlAs_palik", "AlSb",     "AlSb_palik", "Au",
      "Be",         "Be_palik", "Cr",         "CsI",      "CsI_palik",  "Cu",       "Cu_palik",   "Cu2O",
      "Cu2O_palik", "CuO",      "CuO_palik",  "d-C",      "d-C_palik",  "Hg",       "Hg_palik",   "HgTe",
      "HgTe_palik", "Ir",       "Ir_palik",   "K",        "K_palik",    "Li",       "Li_palik",   "MgO",
      "MgO_palik",  "Mo",       "Mo_palik",   "Na_palik", "Nb",         "Nb_palik", "Ni_palik",   "Rh",
      "Rh_palik",   "Se",       "Se_palik",   "SiC",      "SiC_palik",  "SnTe",     "SnTe_palik", "Ta",
      "Ta_palik",   "Te",       "Te_palik",   "ThF4",     "ThF4_palik", "TiC",      "TiC_palik",  "TiN",
      "TiN_palik",  "TiO2",     "TiO2_palik", "VC",       "VC_palik",   "V_palik",  "VN",         "VN_palik",
      "W"};
  int loaded = 0;
  for (const std::string name : names) {
    for (const char* type : {"conductor", "roughconductor"}) {
      const std::string error = test::load_error("<scene version='3.0.0'><bsdf type='" + std::string(type) +
                                                 "'><string name='material' value='" + name + "'/></bsdf></scene>");
      if (error.empty())
        loaded += std::string(type) == "conductor";
      else
        EXPECT_THAT(error, HasSubstr("Mitsuba's measured '" + name + "' is not included")) << name;
    }
  }
  EXPECT_EQ(loaded, 50);
  EXPECT_EQ(conductor_names().size(), 50u);
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><bsdf type='conductor'><string name='material' "
                               "value='Zz'/></bsdf></scene>"),
              HasSubstr("unknown conductor 'Zz' (known: none, Ag, Al, Au, Cu, a-C,"));
}

// RGB transport reads Mitsuba's tables at 650, 550 and 450 nm. Chromium's
// samples around 550 nm (Mitsuba's data/ior/Cr.*.spd): 532.102966 nm (eta
// 2.98, k 4.45) and 558.468018 nm (3.18, 4.41), linear in between; AlSb's
// table ends at 590.381042 nm (4.01, 0.006), where red is held.
TEST(ConductorBsdf, MitsubasTablesAtTheChannelWavelengths) {
  const double t = (550 - 532.102966) / (558.468018 - 532.102966);
  const auto chromium = named_conductor("Cr");
  ASSERT_TRUE(chromium);
  EXPECT_NEAR(chromium->eta.g, 2.98 + t * (3.18 - 2.98), 1e-5);
  EXPECT_NEAR(chromium->k.g, 4.45 + t * (4.41 - 4.45), 1e-5);
  const auto alsb = named_conductor("AlSb");
  ASSERT_TRUE(alsb);
  EXPECT_FLOAT_EQ(alsb->eta.r, 4.01f);
  EXPECT_FLOAT_EQ(alsb->k.r, 0.006f);
  // Spectral transport holds it there too, rather than reading zeros (a mirror).
  EXPECT_FLOAT_EQ(float(alsb->eta_spectrum->at(800)), 4.01f);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
