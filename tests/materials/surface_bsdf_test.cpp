// A BSDF placed on a surface: the combined value-and-density query that
// next-event estimation makes gives exactly what the separate eval and pdf
// give, in both transport modes, for directions on either side of the
// surface, where the shading normal leans away from the geometric one (so
// the side test and the adjoint correction both take part) and for
// materials whose density is not symmetric in its two directions.

#include "core/bsdf/surface_bsdf.h"

#include <gtest/gtest.h>

#include "tests/support/bsdf_checks.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class SurfaceBsdfQueries : public testing::TestWithParam<std::string> {};

TEST_P(SurfaceBsdfQueries, EvalAndPdfIsEvalWithPdf) {
  const auto bsdf = test::make_bsdf(GetParam());
  SurfaceInteraction si;
  si.ng = normalize(Vec3(0.1f, 0.2f, 1));
  si.shading = Frame::from_normal(normalize(Vec3(0.5f, -0.3f, 1)));
  si.uv = {0.3f, 0.7f};
  int compared = 0, nonzero = 0;
  for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
    const SurfaceBsdf surface(*bsdf, si, mode);
    for (float theta_o : {0.1f, 0.9f, 1.45f, 2.2f})
      for (float theta_i : {0.3f, 1.2f, 1.55f, 1.65f, 2.6f})
        for (float phi_i : {0.0f, 2.0f, 4.5f}) {
          const Vec3 wo = test::direction(theta_o, 1.1f), wi = test::direction(theta_i, phi_i);
          const auto [f, pdf] = surface.eval_and_pdf(wo, wi);
          const Color f_alone = surface.eval(wo, wi);
          EXPECT_EQ(f.r, f_alone.r);
          EXPECT_EQ(f.g, f_alone.g);
          EXPECT_EQ(f.b, f_alone.b);
          EXPECT_EQ(pdf, surface.pdf(wo, wi)) << "theta_o " << theta_o << ", theta_i " << theta_i;
          ++compared;
          nonzero += pdf > 0 && !f.is_black();
        }
  }
  // The grid must reach the material's lobes, not only the rejected pairs.
  EXPECT_GT(nonzero, compared / 5);
}

INSTANTIATE_TEST_SUITE_P(Materials, SurfaceBsdfQueries,
                         testing::Values("<bsdf type='diffuse'/>",
                                         "<bsdf type='roughplastic'><float name='alpha' value='0.3'/></bsdf>",
                                         "<bsdf type='roughdielectric'><float name='alpha' value='0.4'/></bsdf>",
                                         "<bsdf type='roughconductor'><float name='alpha_u' value='0.1'/>"
                                         "<float name='alpha_v' value='0.4'/></bsdf>"));

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
