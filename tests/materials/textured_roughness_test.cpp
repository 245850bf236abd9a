// Roughness given as a texture (roughconductor, roughdielectric,
// roughplastic): at each point the material is the one with that point's
// roughness as a constant.
// A checkerboard of alpha 0.05 (where floor(2u) + floor(2v) is even) and 0.4
// must give, at (0.25, 0.25) and (0.75, 0.25), exactly what constant alphas
// of 0.05 and 0.4 give: eval, pdf and samples.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/support/bsdf_checks.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using test::direction;

const char* kCheckers =
    "<texture type='checkerboard' name='alpha'><float name='color0' value='0.05'/>"
    "<float name='color1' value='0.4'/></texture>";

TEST(TexturedRoughness, EachPointIsTheMaterialWithItsRoughness) {
  for (const std::string type : {"roughconductor", "roughdielectric", "roughplastic"}) {
    const auto textured = test::make_bsdf("<bsdf type='" + type + "'>" + kCheckers + "</bsdf>");
    for (const auto& [uv, alpha] : {std::pair{Vec2(0.25f, 0.25f), "0.05"}, std::pair{Vec2(0.75f, 0.25f), "0.4"}}) {
      const auto plain =
          test::make_bsdf("<bsdf type='" + type + "'><float name='alpha' value='" + alpha + "'/></bsdf>");
      BsdfContext ctx;
      ctx.uv = uv;
      test::UniformSource u(3);
      for (int i = 0; i < 200; ++i) {
        const Vec3 wo = direction(0.1f + 1.3f * u.next_1d(), 6.2f * u.next_1d());
        const Vec3 wi = direction(0.1f + 1.3f * u.next_1d(), 6.2f * u.next_1d());
        EXPECT_EQ(textured->eval(ctx, wo, wi).r, plain->eval(ctx, wo, wi).r) << type << " " << alpha;
        EXPECT_EQ(textured->pdf(ctx, wo, wi), plain->pdf(ctx, wo, wi)) << type << " " << alpha;
        const float u_lobe = u.next_1d();
        const Vec2 u2 = u.next_2d();
        const auto a = textured->sample(ctx, wo, u_lobe, u2), b = plain->sample(ctx, wo, u_lobe, u2);
        ASSERT_EQ(a.has_value(), b.has_value());
        if (a) {
          EXPECT_EQ(a->wi, b->wi);
        }
      }
    }
  }
}

TEST(TexturedRoughness, NegativeRoughnessIsRefused) {
  EXPECT_THAT(
      test::load_error("<scene version='3.0.0'><bsdf type='roughconductor'>\n"
                       "<texture type='checkerboard' name='alpha'><float name='color0' value='-0.1'/>"
                       "</texture></bsdf></scene>"),
      testing::HasSubstr("parameter 'alpha' of bsdf 'roughconductor': roughness must be finite and not negative"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
