// Indices of refraction over wavelength against published figures: each
// named material's index at the helium d line (587.56 nm) or sodium D
// (589.3 nm) and its Abbe number, from the makers' and handbooks' tables
// (N-BK7 1.5168 and 64.17; fused silica 1.4585 and 67.8; diamond 2.417 at
// D and about 55; water 1.3330 at D, 20 degrees C, and about 55.7; N-SF11
// 1.78472 and 25.68); the
// models' formulas at hand-computed points; bad coefficients and names.

#include "core/spectral/dispersion.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/thrown_message.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using ::testing::HasSubstr;

TEST(Dispersion, NamedMaterialsMeetTheirPublishedIndices) {
  EXPECT_NEAR(Dispersion::named("bk7").ior(587.56), 1.5168, 1e-4);
  EXPECT_NEAR(Dispersion::named("bk7").abbe_number(), 64.17, 0.05);
  EXPECT_NEAR(Dispersion::named("fused silica").ior(587.56), 1.4585, 1e-4);
  EXPECT_NEAR(Dispersion::named("fused silica").abbe_number(), 67.8, 0.1);
  EXPECT_NEAR(Dispersion::named("diamond").ior(589.3), 2.417, 1e-3);
  EXPECT_NEAR(Dispersion::named("diamond").abbe_number(), 55, 1);
  EXPECT_NEAR(Dispersion::named("water").ior(589.3), 1.3330, 1e-3);
  EXPECT_NEAR(Dispersion::named("water").abbe_number(), 55.7, 1);
  EXPECT_NEAR(Dispersion::named("sf11").ior_d(), 1.78472, 1e-4);
  EXPECT_NEAR(Dispersion::named("sf11").abbe_number(), 25.68, 0.05);
}

TEST(Dispersion, IndicesFallWithWavelength) {
  for (const char* name : {"bk7", "fused silica", "diamond", "water", "sf11"}) {
    const Dispersion d = Dispersion::named(name);
    EXPECT_TRUE(d.is_dispersive());
    for (double nm = 370; nm < 830; nm += 10) EXPECT_GT(d.ior(nm), d.ior(nm + 10)) << name << " at " << nm;
  }
}

TEST(Dispersion, ModelsFollowTheirFormulas) {
  const Dispersion constant = Dispersion::constant(1.33);
  EXPECT_FALSE(constant.is_dispersive());
  EXPECT_EQ(constant.ior(400), 1.33);
  EXPECT_TRUE(std::isinf(constant.abbe_number()));
  // A + B / l^2 + C / l^4 at 0.5 um: 1.5 + 0.004 / 0.25 + 0.0001 / 0.0625.
  EXPECT_NEAR(Dispersion::cauchy({1.5, 0.004, 0.0001}).ior(500), 1.5176, 1e-12);
  // One term, B = 1, C = 0.01 um^2, at 1 um: sqrt(1 + 1 / 0.99).
  EXPECT_NEAR(Dispersion::sellmeier({{1.0, 0.01}}).ior(1000), std::sqrt(1 + 1 / 0.99), 1e-12);
}

TEST(Dispersion, ScenesWriteModelsAsText) {
  EXPECT_EQ(Dispersion::parse("bk7").ior(450), Dispersion::named("bk7").ior(450));
  EXPECT_NEAR(Dispersion::parse("cauchy: 1.5, 0.004, 0.0001").ior(500), 1.5176, 1e-12);
  EXPECT_NEAR(Dispersion::parse("cauchy:1.5 0.004").ior(500), 1.516, 1e-12);
  EXPECT_NEAR(Dispersion::parse("sellmeier: 1.0, 0.01").ior(1000), std::sqrt(1 + 1 / 0.99), 1e-12);
  // Two terms: 1 + 0.5 / (1 - 0.01) + 0.25 / (1 - 0.04) at 1 um.
  EXPECT_NEAR(Dispersion::parse("sellmeier: 0.5 0.01, 0.25 0.04").ior(1000), std::sqrt(1 + 0.5 / 0.99 + 0.25 / 0.96),
              1e-12);
}

TEST(Dispersion, BadModelsAreRefused) {
  const auto message = [](const auto& make) { return test::thrown_message<std::invalid_argument>(make); };
  EXPECT_THAT(message([] { Dispersion::named("flint"); }),
              HasSubstr("no dispersive material is named 'flint' (known: bk7, fused silica, diamond, water, sf11)"));
  EXPECT_THAT(message([] { Dispersion::cauchy({}); }), HasSubstr("Cauchy's model needs at least one coefficient"));
  EXPECT_THAT(message([] {
                Dispersion::sellmeier({{1.0, NAN}});
              }),
              HasSubstr("Sellmeier's model coefficient nan is not finite"));
  EXPECT_THAT(message([] { Dispersion::parse("sellmeier: 1, 0.01, 2"); }),
              HasSubstr("Sellmeier's model takes pairs B, C (3 numbers given)"));
  EXPECT_THAT(message([] { Dispersion::parse("cauchy: 1.5, x"); }), HasSubstr("cannot read 'x' as a number"));
  EXPECT_THAT(message([] { Dispersion::parse("cauchy:"); }),
              HasSubstr("Cauchy's model needs at least one coefficient"));
  EXPECT_THAT(message([] { Dispersion::parse("abbe: 1.5, 60"); }),
              HasSubstr("unknown dispersion model 'abbe' (known: cauchy, sellmeier)"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
