// twosided: seen from the front it is its first BSDF, seen from the back
// its second with directions mirrored through the surface. The back's
// oracle is the nested BSDF made on its own and asked with the mirrored
// directions written out here; samples must stay on the side they were
// asked from (reflection, never transmission), with the usual chi-square,
// sample/eval, reciprocity and furnace checks on both faces.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/bsdf_checks.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using test::below;
using test::direction;

// Chi-square tests in this file: 2 faces x 2 incident angles (counted in kMaterialChi2Tests).
const double kAlpha = test::material_chi2_alpha();

const std::string kFront = "<bsdf type='diffuse'><rgb name='reflectance' value='0.2, 0.5, 0.8'/></bsdf>";
const std::string kBack = "<bsdf type='roughconductor'><float name='alpha' value='0.3'/></bsdf>";

TEST(TwoSidedBsdf, EachFaceIsItsOwnBsdf) {
  const auto bsdf = test::make_bsdf("<bsdf type='twosided'>" + kFront + kBack + "</bsdf>");
  const auto front = test::make_bsdf(kFront), back = test::make_bsdf(kBack);
  EXPECT_EQ(bsdf->lobes(), uint32_t(kDiffuseReflection | kGlossyReflection));
  for (const bool from_back : {false, true})
    for (const float theta : {0.4f, 1.2f}) {
      const Vec3 up = direction(theta), wo = from_back ? below(up) : up;
      const auto chi2 = test::chi2_bsdf(*bsdf, wo, {}, {.sample_count = 200000, .bins_u = 20, .bins_v = 40});
      EXPECT_GT(chi2.p_value, kAlpha) << (from_back ? "back" : "front") << " theta " << theta << "\n" << chi2.report;
      const auto c = test::check_samples(*bsdf, wo, {}, 4000);
      EXPECT_GT(c.checked, 3000);
      EXPECT_LT(c.max_f_error, 1e-6);
      EXPECT_LT(c.max_pdf_error, 1e-6);
      EXPECT_EQ(c.non_finite, 0);
      // Reflection only: every sample leaves on wo's side.
      test::UniformSource u(5);
      for (int i = 0; i < 1000; ++i) {
        const auto s = bsdf->sample({}, wo, u.next_1d(), u.next_2d());
        if (s) {
          EXPECT_GT(s->wi.z * wo.z, 0) << (from_back ? "back" : "front");
        }
      }
      const Bsdf& face = from_back ? *back : *front;
      EXPECT_NEAR(test::pdf_integral(*bsdf, wo, {}), test::pdf_integral(face, up, {}), 1e-4);
      for (const Vec3 wi_up : {direction(0.3f, 2.0f), direction(1.0f, 4.0f)}) {
        const Vec3 wi = from_back ? below(wi_up) : wi_up;
        EXPECT_EQ(bsdf->eval({}, wo, wi), face.eval({}, up, wi_up));
        EXPECT_EQ(bsdf->pdf({}, wo, wi), face.pdf({}, up, wi_up));
        // Across the surface nothing is scattered.
        EXPECT_EQ(bsdf->eval({}, wo, from_back ? wi_up : below(wi_up)), Color());
      }
      const Color a = bsdf->albedo({}, wo), want = face.albedo({}, up);
      for (int ch = 0; ch < 3; ++ch) EXPECT_FLOAT_EQ(a[ch], want[ch]);
    }
  EXPECT_LT(test::reciprocity_error(*bsdf, {}, 2000), 1e-5);
}

// One nested white diffuse serves both faces: the furnace is one from
// either side, and each side mirrors the other exactly.
TEST(TwoSidedBsdf, OneBsdfOnBothFacesIsWhiteBothWays) {
  const auto bsdf =
      test::make_bsdf("<bsdf type='twosided'><bsdf type='diffuse'><rgb name='reflectance' value='1'/></bsdf></bsdf>");
  for (const float theta : {0.2f, 1.4f}) {
    for (const Vec3 wo : {direction(theta), below(direction(theta))}) {
      const auto a = test::albedo(*bsdf, wo, {}, 20000);
      EXPECT_NEAR(a.mean.g, 1, 1e-5);
      EXPECT_LT(a.standard_error.g, 1e-5);  // f |cos| / pdf is exactly one per sample
    }
    EXPECT_EQ(bsdf->eval({}, direction(theta), direction(0.7f, 1.0f)),
              bsdf->eval({}, below(direction(theta)), below(direction(0.7f, 1.0f))));
  }
}

TEST(TwoSidedBsdf, BadNesting) {
  EXPECT_THAT(
      test::load_error("<scene version='3.0.0'><bsdf type='twosided'>" + kFront + kFront + kFront + "</bsdf></scene>"),
      testing::HasSubstr("bsdf 'twosided' takes one or two nested bsdfs, found 3"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><bsdf type='twosided'><bsdf type='dielectric'/></bsdf></scene>"),
              testing::HasSubstr("bsdf 'twosided' cannot wrap a bsdf that transmits light"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
