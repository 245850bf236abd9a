#include <gtest/gtest.h>

#include "core/math/constants.h"
#include "tests/support/bsdf_checks.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using test::direction;

// Chi-square tests in this file: 4 incident angles x 2 modes (counted in kMaterialChi2Tests).
const double kAlpha = test::material_chi2_alpha();

TEST(DiffuseBsdf, SamplesFollowThePdf) {
  const auto bsdf = test::make_bsdf("<bsdf type='diffuse'><rgb name='reflectance' value='0.2, 0.5, 0.8'/></bsdf>");
  for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance})
    for (float theta : {0.0f, 0.7f, 1.4f, 1.5607f}) {  // down to 0.01 rad from grazing
      const BsdfContext ctx{mode, {}};
      const Vec3 wo = direction(theta);
      const auto chi2 = test::chi2_bsdf(*bsdf, wo, ctx, {.sample_count = 200000, .bins_u = 20, .bins_v = 40});
      EXPECT_GT(chi2.p_value, kAlpha) << "theta " << theta << "\n" << chi2.report;
      const auto c = test::check_samples(*bsdf, wo, ctx, 2000);
      EXPECT_GT(c.checked, 1900);
      EXPECT_LT(c.max_f_error, 1e-6);
      EXPECT_LT(c.max_pdf_error, 1e-5);
      EXPECT_EQ(c.non_finite, 0);
      EXPECT_NEAR(test::pdf_integral(*bsdf, wo, ctx), 1.0, 1e-3);
    }
}

TEST(DiffuseBsdf, WhiteFurnaceAndReciprocity) {
  const auto white = test::make_bsdf("<bsdf type='diffuse'><rgb name='reflectance' value='1'/></bsdf>");
  for (float theta : {0.0f, 1.0f, 1.55f}) {
    const auto a = test::albedo(*white, direction(theta), {}, 10000);
    // Cosine sampling makes f cos / pdf exactly the reflectance.
    EXPECT_NEAR(a.mean.r, 1.0f, 1e-5f);
    EXPECT_NEAR(a.standard_error.r, 0.0f, 1e-5f);
  }
  EXPECT_LT(test::reciprocity_error(*white, {}, 1000), 1e-6);
  EXPECT_EQ(white->eval({}, direction(0.3f), Vec3(0, 0, -1)), Color());  // no transmission
  EXPECT_EQ(white->eval({}, Vec3(0, 0, -1), direction(0.3f)), Color());  // one-sided
  EXPECT_FLOAT_EQ(white->eval({}, direction(0.3f), direction(1.2f)).g, kInvPi);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
