#include "core/bsdf/fresnel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <utility>

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

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

// Against the Fresnel equations written the other way, by angles (rs =
// -sin(i - t) / sin(i + t), rp = tan(i - t) / tan(i + t), in double), at
// many angles from outside and inside, for indices above and below one.
// Each polarisation is checked on its own where the other vanishes: at
// Brewster's angle (tan i = eta) rp is zero and F is rs^2 / 2.
TEST(FresnelDielectric, MatchesTheEquationsByAngles) {
  for (const double eta : {1.1, 1.33, 1.5046, 2.42, 0.763}) {
    for (int k = 1; k < 90; ++k) {
      const double i = (k - 0.5) * M_PI / 180;  // 0.5 to 88.5 degrees
      for (const bool inside : {false, true}) {
        const double rel = inside ? 1 / eta : eta;  // n_t / n_i
        const double sin_t = std::sin(i) / rel;
        const float F = fresnel_dielectric(float(inside ? -std::cos(i) : std::cos(i)), float(eta)).F;
        if (sin_t >= 1) {
          EXPECT_EQ(F, 1) << eta << " " << k << (inside ? " inside" : "");
          continue;
        }
        const double t = std::asin(sin_t);
        const double rs = -std::sin(i - t) / std::sin(i + t), rp = std::tan(i - t) / std::tan(i + t);
        EXPECT_NEAR(F, (rs * rs + rp * rp) / 2, 2e-6) << eta << " at " << k << (inside ? " inside" : "");
      }
    }
    const double brewster = std::atan(eta), t = std::asin(std::sin(brewster) / eta);
    const double rs = std::sin(brewster - t) / std::sin(brewster + t);
    EXPECT_NEAR(fresnel_dielectric(float(std::cos(brewster)), float(eta)).F, rs * rs / 2, 2e-6) << eta;
  }
}

// Against the complex Fresnel equations with n = eta + i k (std::complex,
// double) at oblique angles, for metals' typical indices.
TEST(FresnelConductor, MatchesTheComplexEquationsAtEveryAngle) {
  const std::pair<double, double> metals[] = {{0.2, 3.9}, {1.1, 6.0}, {2.9, 3.0}, {0.05, 2.1}, {1.5, 0.3}};
  for (const auto& [eta, k] : metals)
    for (int a = 0; a < 90; a += 3) {
      const double i = a * M_PI / 180, c = std::cos(i), s2 = 1 - c * c;
      const std::complex<double> n(eta, k), root = std::sqrt(n * n - s2);
      const double rs = std::norm((c - root) / (c + root)), rp = std::norm((n * n * c - root) / (n * n * c + root));
      EXPECT_NEAR(fresnel_conductor(float(c), float(eta), float(k)), (rs + rp) / 2, 2e-5)
          << "eta " << eta << " k " << k << " at " << a;
    }
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

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
