// The rough coating's albedo table (roughplastic's E): near alpha 0 it is
// the smooth interface's Fresnel reflectance, written out here; at any
// roughness it is the reflected albedo integrated over microfacet normals
// apart from core/bsdf; across a roughness range it interpolates what a
// table made for the one roughness gives, and at the range's ends it is
// that table exactly.

#include "core/bsdf/coating_albedo.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/microfacet_oracle.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

constexpr float kEta = 1.49f;

double fresnel(double mu, double eta) {
  const double cos_t = std::sqrt(1 - (1 - mu * mu) / (eta * eta));
  const double rs = (mu - eta * cos_t) / (mu + eta * cos_t), rp = (eta * mu - cos_t) / (eta * mu + cos_t);
  return (rs * rs + rp * rp) / 2;
}

TEST(CoatingAlbedo, SmoothLimitIsFresnel) {
  for (const auto type : {MicrofacetDistribution::Type::Beckmann, MicrofacetDistribution::Type::GGX}) {
    const CoatingAlbedo e(type, 0.001f, 0.001f, kEta);
    for (const float mu : {1.0f, 0.7f, 0.4f, 0.2f}) EXPECT_NEAR(e(0.001f, mu), fresnel(mu, kEta), 2e-3) << mu;
  }
}

TEST(CoatingAlbedo, RangeInterpolatesSingleTables) {
  const auto type = MicrofacetDistribution::Type::GGX;
  const CoatingAlbedo range(type, 0.05f, 0.6f, kEta);
  for (const float alpha : {0.05f, 0.17f, 0.33f, 0.6f}) {
    const CoatingAlbedo single(type, alpha, alpha, kEta);
    const bool end = alpha == 0.05f || alpha == 0.6f;
    for (const float mu : {1.0f, 0.5f, 0.1f, 0.02f}) {
      if (end)
        EXPECT_EQ(range(alpha, mu), single(alpha, mu));
      else
        EXPECT_NEAR(range(alpha, mu), single(alpha, mu), 2e-3) << alpha << " " << mu;
    }
    EXPECT_NEAR(range.mean(alpha), single.mean(alpha), end ? 0 : 2e-3);
  }
  // A range too narrow to resolve is one roughness, not a division by zero.
  const CoatingAlbedo narrow(type, 0.3f, std::nextafter(0.3f, 1.0f), kEta);
  EXPECT_EQ(narrow(0.3f, 0.5f), CoatingAlbedo(type, 0.3f, 0.3f, kEta)(0.3f, 0.5f));
  // Outside the range, the nearest end.
  EXPECT_EQ(range(0.9f, 0.5f), range(0.6f, 0.5f));
  EXPECT_EQ(range(0.0f, 0.5f), range(0.05f, 0.5f));
}

// The table against the albedo integrated over microfacet normals apart
// from core/bsdf (tests/support/microfacet_oracle): the reflected share of a
// rough dielectric interface, which is what E is, at roughness from near
// smooth to very rough and at every angle down to near grazing; and its
// cosine-weighted mean by the midpoint rule over the same oracle.
TEST(CoatingAlbedo, MatchesTheAlbedoIntegratedOverNormals) {
  for (const auto type : {MicrofacetDistribution::Type::Beckmann, MicrofacetDistribution::Type::GGX})
    for (const float alpha : {0.05f, 0.3f, 0.8f}) {
      const CoatingAlbedo e(type, alpha, alpha, kEta);
      const test::MicrofacetModel model{type == MicrofacetDistribution::Type::GGX, alpha, alpha};
      const auto oracle = [&](double mu, int n) {
        const Vec3 wo(float(std::sqrt(1 - mu * mu)), 0, float(mu));
        return test::microfacet_albedo(model, {true, kEta}, wo, n).reflected;
      };
      for (const float mu : {1.0f, 0.7f, 0.4f, 0.15f, 0.05f}) {
        const double fine = oracle(mu, 300), coarse = oracle(mu, 150);
        EXPECT_NEAR(e(alpha, mu), fine, 2e-3 + std::abs(fine - coarse)) << alpha << " mu " << mu;
      }
      double mean = 0;
      constexpr int kSteps = 64;
      for (int i = 0; i < kSteps; ++i) {
        const double mu = (i + 0.5) / kSteps;
        mean += 2 * oracle(mu, 100) * mu / kSteps;
      }
      EXPECT_NEAR(e.mean(alpha), mean, 3e-3) << alpha;
    }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
