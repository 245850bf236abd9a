#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
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
using namespace test::burley;

// Chi-square tests in this file: 4 sheets x 4 directions (counted in kMaterialChi2Tests).
const double kAlpha = test::material_chi2_alpha();

struct Sheet {
  double base[3] = {0.5, 0.5, 0.5};
  double roughness = 0.5, anisotropic = 0, spec_trans = 0, eta = 1.5, spec_tint = 0, sheen = 0, sheen_tint = 0,
         flatness = 0, diff_trans = 0;

  std::string xml() const {
    const auto f = [](const char* name, double v) {
      return "<float name='" + std::string(name) + "' value='" + std::to_string(v) + "'/>";
    };
    return "<bsdf type='principledthin'><rgb name='base_color' value='" + std::to_string(base[0]) + ", " +
           std::to_string(base[1]) + ", " + std::to_string(base[2]) + "'/>" + f("roughness", roughness) +
           f("anisotropic", anisotropic) + f("spec_trans", spec_trans) + f("eta", eta) + f("spec_tint", spec_tint) +
           f("sheen", sheen) + f("sheen_tint", sheen_tint) + f("flatness", flatness) + f("diff_trans", diff_trans) +
           "</bsdf>";
  }
};

Sheet leaf() {
  Sheet s;
  s.base[0] = 0.2, s.base[1] = 0.6, s.base[2] = 0.1;
  s.roughness = 0.6, s.diff_trans = 0.8, s.sheen = 0.5, s.sheen_tint = 0.4, s.flatness = 0.3;
  return s;
}

Sheet pane() {
  Sheet s;
  s.base[0] = s.base[1] = s.base[2] = 0.95;
  s.roughness = 0.2, s.spec_trans = 1, s.eta = 1.5;
  return s;
}

Sheet everything() {
  Sheet s;
  s.base[0] = 0.7, s.base[1] = 0.1, s.base[2] = 0.1;
  s.roughness = 0.35, s.anisotropic = 0.5, s.spec_trans = 0.6, s.eta = 1.33, s.spec_tint = 0.4, s.sheen = 0.7,
  s.flatness = 0.5, s.diff_trans = 1.2;
  return s;
}

// Burley's thin surface, written apart from the plugin: wo turned up, the
// light through the sheet as the reflection of wi mirrored, with roughness
// scaled by 0.65 eta - 0.35 (2015, figure 15).
std::array<double, 3> published(const Sheet& s, Dir v, Dir l) {
  if (v.z < 0) {
    v = {-v.x, -v.y, -v.z};
    l = {-l.x, -l.y, -l.z};
  }
  std::array<double, 3> out{};
  const double diffuse_w = (1 - s.spec_trans) * (1 - s.diff_trans / 2),
               through_w = (1 - s.spec_trans) * s.diff_trans / 2;
  const Dir r{l.x, l.y, std::abs(l.z)};
  const Dir h = unit({v.x + r.x, v.y + r.y, v.z + r.z});
  const double vh = dot3(v, h), fh = schlick(vh), F_d = fresnel(vh, 1, s.eta);
  const double lum = 0.2126 * s.base[0] + 0.7152 * s.base[1] + 0.0722 * s.base[2];
  const double r0 = (s.eta - 1) * (s.eta - 1) / ((s.eta + 1) * (s.eta + 1));
  for (int c = 0; c < 3; ++c) {
    if (l.z > 0) {
      const Alphas a = alphas(s.roughness, s.anisotropic);
      const double tint = s.base[c] / lum;
      const double F = (1 - s.spec_tint) * F_d + s.spec_tint * (tint * r0 + (1 - tint * r0) * fh);
      const double spec = s.spec_trans * F * ggx_D(h, a) * ggx_visibility(v, a) * ggx_visibility(r, a);
      const double sheen = s.sheen * (1 + s.sheen_tint * (tint - 1)) * fh;
      out[c] = spec + diffuse_w * (s.base[c] * diffuse(l.z, v.z, dot3(l, h), s.roughness, s.flatness) + sheen);
    } else {
      const Alphas a = alphas((0.65 * s.eta - 0.35) * s.roughness, s.anisotropic);
      const double glass =
          s.spec_trans * s.base[c] * (1 - F_d) * ggx_D(h, a) * ggx_visibility(v, a) * ggx_visibility(r, a);
      out[c] = glass + through_w * s.base[c] / kPi;
    }
  }
  return out;
}

TEST(PrincipledThinBsdf, MatchesThePublishedModel) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> u(0, 1);
  for (const Sheet& s : {Sheet{}, leaf(), pane(), everything()}) {
    const auto bsdf = test::make_bsdf(s.xml());
    for (int i = 0; i < 400; ++i) {
      const float theta_o = std::acos(2 * u(rng) - 1), theta_i = std::acos(2 * u(rng) - 1);
      const Vec3 wo = direction(theta_o, 2 * kPi * u(rng)), wi = direction(theta_i, 2 * kPi * u(rng));
      if (std::abs(wo.z) < 0.02f || std::abs(wi.z) < 0.02f) continue;
      const auto expected = published(s, {wo.x, wo.y, wo.z}, {wi.x, wi.y, wi.z});
      const Color f = bsdf->eval(kRadiance, wo, wi);
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(f[c], expected[c], 2e-3 * expected[c] + 1e-6)
            << s.xml() << "\nwo " << wo.x << " " << wo.y << " " << wo.z << " wi " << wi.x << " " << wi.y << " " << wi.z
            << " channel " << c;
    }
  }
}

TEST(PrincipledThinBsdf, SamplesFollowThePdfFromEitherFace) {
  for (const Sheet& s : {Sheet{}, leaf(), pane(), everything()}) {
    const auto bsdf = test::make_bsdf(s.xml());
    for (Vec3 wo : {direction(0.3f), direction(1.2f), direction(1.5607f), below(direction(0.8f))}) {
      const auto chi2 = test::chi2_bsdf(*bsdf, wo, kRadiance, {.sample_count = 200000, .bins_u = 40, .bins_v = 80});
      EXPECT_GT(chi2.p_value, kAlpha) << s.xml() << " wo.z " << wo.z << "\n" << chi2.report;
      const auto c = test::check_samples(*bsdf, wo, kRadiance, 2000);
      EXPECT_GT(c.checked, 1000) << s.xml();
      EXPECT_LT(c.max_f_error, 1e-4) << s.xml();
      EXPECT_LT(c.max_pdf_error, 1e-4) << s.xml();
      EXPECT_EQ(c.non_finite, 0) << s.xml();
      const double integral = test::pdf_integral(*bsdf, wo, kRadiance);
      EXPECT_LE(integral, 1 + 1e-3) << s.xml();
      EXPECT_GT(integral, 0.5) << s.xml();
    }
  }
}

// A sheet has no inside: both faces alike, reciprocal through it too, and
// the two transport modes the same (nothing bends).
TEST(PrincipledThinBsdf, FacesAlikeReciprocalAndModeFree) {
  for (const Sheet& s : {Sheet{}, leaf(), pane(), everything()}) {
    const auto bsdf = test::make_bsdf(s.xml());
    EXPECT_LT(test::reciprocity_error(*bsdf, kRadiance, 2000, true), 1e-4) << s.xml();
    for (const auto& [wo, wi] : {std::pair{direction(0.4f, 0.2f), direction(0.9f, 2.0f)},
                                 {direction(0.4f, 0.2f), below(direction(0.5f, 3.0f))}}) {
      EXPECT_EQ(bsdf->eval(kRadiance, wo, wi), bsdf->eval(kRadiance, -wo, -wi)) << s.xml();
      EXPECT_EQ(bsdf->eval(kRadiance, wo, wi), bsdf->eval(kImportance, wo, wi)) << s.xml();
    }
  }
}

// A white, smooth, clear pane reflects and lets through all but what
// masking takes; a white diffuse sheet of roughness 0 sends on at most all.
TEST(PrincipledThinBsdf, WhiteFurnace) {
  Sheet clear = pane();
  clear.base[0] = clear.base[1] = clear.base[2] = 1;
  clear.roughness = 0.05;
  Sheet paper;
  paper.base[0] = paper.base[1] = paper.base[2] = 1;
  paper.roughness = 0, paper.diff_trans = 1;
  for (float theta : {0.0f, 0.8f, 1.3f}) {
    const auto a = test::albedo(*test::make_bsdf(clear.xml()), direction(theta), kRadiance, 40000);
    EXPECT_LE(a.mean.g, 1 + 4 * a.standard_error.g) << theta;
    EXPECT_GT(a.mean.g, 0.97f) << theta;
    const auto b = test::albedo(*test::make_bsdf(paper.xml()), direction(theta), kRadiance, 40000);
    EXPECT_LE(b.mean.g, 1 + 4 * b.standard_error.g) << theta;
    EXPECT_GT(b.mean.g, 0.8f) << theta;
  }
}

TEST(PrincipledThinBsdf, BadParametersNameThemselves) {
  const auto error = [](const std::string& inner) {
    return test::load_error("<scene version='3.0.0'>\n<bsdf type='principledthin'>\n" + inner + "</bsdf></scene>",
                            "bad.xml");
  };
  EXPECT_THAT(error("<float name='diff_trans' value='2.5'/>"),
              HasSubstr("bad.xml:3: parameter 'diff_trans' of bsdf 'principledthin': must lie in [0, 2]"));
  EXPECT_THAT(error("<float name='eta' value='0'/>"),
              HasSubstr("parameter 'eta' of bsdf 'principledthin': must be positive"));
  EXPECT_THAT(error("<float name='spec_trans' value='1.5'/>"),
              HasSubstr("parameter 'spec_trans' of bsdf 'principledthin': must lie in [0, 1]"));
  EXPECT_THAT(error("<float name='diffuse_transmittance_sampling_rate' value='0'/>"), HasSubstr("must be positive"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
