// Which materials read the surface's tangents: a surface transforms them
// into the shading frame only for those that say they do, so every
// material that says it does not must give the same values whatever the
// tangents are, and the perturbed-frame materials, alone or nested, must
// say they do.

#include <gtest/gtest.h>

#include "core/bsdf/bsdf.h"
#include "tests/support/bsdf_checks.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

const char* const kDiffuse = "<bsdf type='diffuse'/>";
const char* const kBump = "<bsdf type='bumpmap'><texture type='checkerboard'/><bsdf type='diffuse'/></bsdf>";

class IgnoresTangents : public testing::TestWithParam<std::string> {};

TEST_P(IgnoresTangents, ValuesDoNotDependOnTheTangents) {
  const auto bsdf = test::make_bsdf(GetParam());
  ASSERT_FALSE(bsdf->reads_tangents());
  BsdfContext plain, tilted;
  plain.uv = tilted.uv = {0.3f, 0.6f};
  tilted.dpdu = {0.2f, 0.9f, 0.4f};
  tilted.dpdv = {-3, 0.5f, 0.1f};
  for (float theta_o : {0.2f, 1.0f, 1.5f})
    for (float theta_i : {0.1f, 0.8f, 2.5f}) {
      const Vec3 wo = test::direction(theta_o, 0.4f), wi = test::direction(theta_i, 2.1f);
      const Color a = bsdf->eval(plain, wo, wi), b = bsdf->eval(tilted, wo, wi);
      EXPECT_EQ(a.r, b.r);
      EXPECT_EQ(a.g, b.g);
      EXPECT_EQ(bsdf->pdf(plain, wo, wi), bsdf->pdf(tilted, wo, wi));
      const auto sa = bsdf->sample(plain, wo, 0.37f, {0.21f, 0.68f});
      const auto sb = bsdf->sample(tilted, wo, 0.37f, {0.21f, 0.68f});
      ASSERT_EQ(bool(sa), bool(sb));
      if (sa) {
        EXPECT_EQ(sa->wi.x, sb->wi.x);
        EXPECT_EQ(sa->f.g, sb->f.g);
        EXPECT_EQ(sa->pdf, sb->pdf);
      }
      EXPECT_EQ(bsdf->albedo(plain, wo).g, bsdf->albedo(tilted, wo).g);
    }
}

INSTANTIATE_TEST_SUITE_P(
    Materials, IgnoresTangents,
    testing::Values(kDiffuse, "<bsdf type='phong'/>", "<bsdf type='plastic'/>", "<bsdf type='roughplastic'/>",
                    "<bsdf type='roughconductor'><float name='alpha_u' value='0.1'/>"
                    "<float name='alpha_v' value='0.4'/></bsdf>",
                    "<bsdf type='roughdielectric'/>", "<bsdf type='conductor'/>", "<bsdf type='dielectric'/>",
                    "<bsdf type='thindielectric'/>", std::string("<bsdf type='twosided'>") + kDiffuse + "</bsdf>",
                    std::string("<bsdf type='mask'>") + kDiffuse + "</bsdf>",
                    std::string("<bsdf type='blendbsdf'>") + kDiffuse + "<bsdf type='roughconductor'/></bsdf>"));

TEST(TangentUse, PerturbedFramesReadThemAloneAndNested) {
  EXPECT_TRUE(test::make_bsdf(kBump)->reads_tangents());
  EXPECT_TRUE(test::make_bsdf("<bsdf type='normalmap'><rgb name='normalmap' value='0.5, 0.5, 1'/>"
                              "<bsdf type='diffuse'/></bsdf>")
                  ->reads_tangents());
  EXPECT_TRUE(test::make_bsdf(std::string("<bsdf type='twosided'>") + kDiffuse + kBump + "</bsdf>")->reads_tangents());
  EXPECT_TRUE(test::make_bsdf(std::string("<bsdf type='mask'>") + kBump + "</bsdf>")->reads_tangents());
  EXPECT_TRUE(test::make_bsdf(std::string("<bsdf type='blendbsdf'>") + kBump + kDiffuse + "</bsdf>")->reads_tangents());
  EXPECT_TRUE(test::make_bsdf(std::string("<bsdf type='blendbsdf'>") + kDiffuse + kBump + "</bsdf>")->reads_tangents());
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
