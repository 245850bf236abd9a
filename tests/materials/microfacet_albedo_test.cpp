// The white furnace of the rough conductor and the rough dielectric against
// their albedo computed by quadrature over microfacet normals in the test
// (tests/support/microfacet_oracle), not through the BSDFs: the Monte Carlo
// albedo of each BSDF's own sampling must match it within a z-test at 1%
// (Sidak-corrected over the cases) plus the quadrature's error. A lost lobe,
// a Fresnel share at the wrong angle or a masking term with a wrong
// exponent moves the albedo by far more than that margin.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "tests/support/bsdf_checks.h"
#include "tests/support/microfacet_oracle.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using test::below;
using test::direction;

struct Case {
  const char* distribution;
  float alpha_u, alpha_v;
};

const Case kConductors[] = {{"ggx", 0.05f, 0.05f},    {"ggx", 0.3f, 0.3f},        {"ggx", 1.0f, 1.0f},
                            {"ggx", 0.05f, 0.4f},     {"beckmann", 0.05f, 0.05f}, {"beckmann", 0.3f, 0.3f},
                            {"beckmann", 1.0f, 1.0f}, {"beckmann", 0.4f, 0.1f}};
const Case kDielectrics[] = {{"ggx", 0.05f, 0.05f},      {"ggx", 0.3f, 0.3f},      {"ggx", 0.8f, 0.8f},
                             {"beckmann", 0.05f, 0.05f}, {"beckmann", 0.3f, 0.3f}, {"beckmann", 0.8f, 0.8f}};
const float kThetas[] = {0.0f, 0.7f, 1.2f, 1.5607f};
const float kEtas[] = {1.5f, 1.33f};
constexpr int kSamples = 40000;
// Quadrature points: 300 by 600, whose error the test estimates by halving them.
constexpr int kPoints = 300;
// Conductors 8 x 4 angles; dielectrics 6 x 2 indices x 2 sides x 4 angles
// x 2 transport modes.
constexpr int kTests = 8 * 4 + 6 * 2 * 2 * 4 * 2;
const double kZ = test::two_sided_z_critical(test::sidak_alpha(0.01, kTests));

test::MicrofacetModel model(const Case& c) { return {std::string(c.distribution) == "ggx", c.alpha_u, c.alpha_v}; }

std::string roughness(const Case& c) {
  return "<string name='distribution' value='" + std::string(c.distribution) + "'/><float name='alpha_u' value='" +
         std::to_string(c.alpha_u) + "'/><float name='alpha_v' value='" + std::to_string(c.alpha_v) + "'/>";
}

// The quadrature at two resolutions: the change from half the points
// estimates the error of the finer one.
struct Quadrature {
  test::MicrofacetAlbedo fine, coarse;
};
Quadrature quadrature(const test::MicrofacetModel& m, const test::Interface& interface, Vec3 wo) {
  return {test::microfacet_albedo(m, interface, wo, kPoints), test::microfacet_albedo(m, interface, wo, kPoints / 2)};
}

// `albedo` picks the transport mode's quantity out of the quadrature.
void expect_albedo(const Bsdf& bsdf, Vec3 wo, const BsdfContext& ctx, const Quadrature& q,
                   const std::function<double(const test::MicrofacetAlbedo&)>& albedo, const std::string& what) {
  const double expected = albedo(q.fine), error = std::abs(expected - albedo(q.coarse)) + 1e-4;
  EXPECT_LT(error, 2e-3) << what;
  const auto a = test::albedo(bsdf, wo, ctx, kSamples, 11);
  EXPECT_NEAR(a.mean.g, expected, kZ * a.standard_error.g + error)
      << what << ": Monte Carlo " << a.mean.g << " +- " << a.standard_error.g << ", quadrature " << expected;
}

TEST(MicrofacetAlbedo, RoughMirrorMatchesQuadrature) {
  for (const Case& c : kConductors) {
    const auto bsdf = test::make_bsdf("<bsdf type='roughconductor'>" + roughness(c) + "</bsdf>");
    for (float theta : kThetas) {
      const Vec3 wo = direction(theta);
      const std::string what = std::string(c.distribution) + " " + std::to_string(c.alpha_u) + "/" +
                               std::to_string(c.alpha_v) + " theta " + std::to_string(theta);
      expect_albedo(*bsdf, wo, {}, quadrature(model(c), {}, wo), &test::MicrofacetAlbedo::importance, what);
    }
  }
}

TEST(MicrofacetAlbedo, RoughDielectricMatchesQuadrature) {
  for (const Case& c : kDielectrics)
    for (float eta : kEtas) {
      const auto bsdf =
          test::make_bsdf("<bsdf type='roughdielectric'>" + roughness(c) + test::ior_params(eta) + "</bsdf>");
      for (float theta : kThetas)
        for (const bool inside : {false, true}) {
          const Vec3 up = direction(theta), wo = inside ? below(up) : up;
          // From inside, the same interface seen upside down.
          const test::Interface interface { true, inside ? 1.0 / eta : eta };
          const Quadrature q = quadrature(model(c), interface, up);
          const std::string what = std::string(c.distribution) + " " + std::to_string(c.alpha_u) + " eta " +
                                   std::to_string(eta) + (inside ? " inside" : " outside") + " theta " +
                                   std::to_string(theta);
          const auto radiance = [&](const test::MicrofacetAlbedo& a) { return a.radiance(interface.eta); };
          expect_albedo(*bsdf, wo, test::kRadiance, q, radiance, what + " radiance");
          expect_albedo(*bsdf, wo, test::kImportance, q, &test::MicrofacetAlbedo::importance, what + " importance");
        }
    }
}

// The oracle itself: a flat mirror's limit and Beckmann's Lambda at a
// value worked out by hand, so that a wrong quadrature cannot pass as a
// wrong BSDF.
TEST(MicrofacetAlbedo, QuadratureOracleReproducesKnownValues) {
  const Vec3 wo = direction(0.5f);
  EXPECT_NEAR(test::microfacet_albedo({true, 1e-4, 1e-4}, {}, wo, 200).importance(), 1.0, 1e-4);
  // Smooth glass at normal incidence: R = 0.04, T = 0.96.
  const auto glass = test::microfacet_albedo({true, 1e-4, 1e-4}, {true, 1.5}, Vec3(0, 0, 1), 200);
  EXPECT_NEAR(glass.reflected, 0.04, 1e-4);
  EXPECT_NEAR(glass.refracted, 0.96, 1e-4);
  // Beckmann at tan theta = 1 / alpha: a = 1, Lambda = (erf(1) - 1) / 2 + exp(-1) / (2 sqrt(pi)).
  const float theta = std::atan(1 / 0.5f);
  EXPECT_NEAR(test::smith_lambda({false, 0.5, 0.5}, direction(theta)),
              (0.8427007929 - 1) / 2 + 0.3678794412 / (2 * 1.7724538509), 1e-6);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
