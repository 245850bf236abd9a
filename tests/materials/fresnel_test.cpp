#include "core/bsdf/fresnel.h"

#include <gtest/gtest.h>

#include <cmath>

namespace caustica {
namespace {

TEST(FresnelDielectric, NormalIncidenceAndIndexMatching) {
  // ((eta - 1) / (eta + 1))^2 at normal incidence, from either side.
  EXPECT_NEAR(fresnel_dielectric(1, 1.5f).F, 0.04f, 1e-6f);
  EXPECT_NEAR(fresnel_dielectric(-1, 1.5f).F, 0.04f, 1e-6f);
  const auto matched = fresnel_dielectric(0.3f, 1.0f);
  EXPECT_NEAR(matched.F, 0, 1e-7f);
  EXPECT_NEAR(matched.cos_t, -0.3f, 1e-6f);  // straight through
}

TEST(FresnelDielectric, TotalInternalReflectionAndGrazing) {
  // From glass (n = 1.5) the critical angle is asin(1 / 1.5) = 41.8 degrees.
  const float critical = std::asin(1 / 1.5f);
  EXPECT_EQ(fresnel_dielectric(-std::cos(critical + 0.01f), 1.5f).F, 1);
  EXPECT_EQ(fresnel_dielectric(-std::cos(critical + 0.01f), 1.5f).cos_t, 0);
  EXPECT_LT(fresnel_dielectric(-std::cos(critical - 0.01f), 1.5f).F, 1);
  EXPECT_NEAR(fresnel_dielectric(1e-6f, 1.5f).F, 1, 1e-4f);
  // Snell's law: sin_t = sin_i / eta.
  const auto f = fresnel_dielectric(std::cos(0.6f), 1.33f);
  EXPECT_NEAR(std::sqrt(1 - f.cos_t * f.cos_t), std::sin(0.6f) / 1.33f, 1e-6f);
}

TEST(FresnelConductor, ReducesToDielectricWithoutAbsorption) {
  for (float c : {1.0f, 0.7f, 0.2f, 0.01f})
    EXPECT_NEAR(fresnel_conductor(c, 1.5f, 0.0f), fresnel_dielectric(c, 1.5f).F, 1e-5f) << c;
  // Normal incidence: ((eta - 1)^2 + k^2) / ((eta + 1)^2 + k^2).
  EXPECT_NEAR(fresnel_conductor(1, 0.2f, 3.9f), (0.64f + 15.21f) / (1.44f + 15.21f), 1e-5f);
  EXPECT_NEAR(fresnel_conductor(1e-7f, 0.2f, 3.9f), 1, 1e-4f);
}

TEST(Reflection, MirrorsAndRefracts) {
  const Vec3 n(0, 0, 1), w = normalize(Vec3(0.3f, -0.2f, 0.9f));
  const Vec3 r = reflect(w, n);
  EXPECT_NEAR(r.x, -w.x, 1e-6f);
  EXPECT_NEAR(r.z, w.z, 1e-6f);
  const auto f = fresnel_dielectric(w.z, 1.5f);
  const Vec3 t = refract(w, n, f.cos_t, f.eta_ti);
  EXPECT_NEAR(length(t), 1, 1e-6f);
  EXPECT_NEAR(t.z, f.cos_t, 1e-6f);
  EXPECT_NEAR(t.x, -w.x * f.eta_ti, 1e-6f);  // tangential part scaled by 1 / eta
}

}  // namespace
}  // namespace caustica
