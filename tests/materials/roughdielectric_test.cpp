#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/bsdf/fresnel.h"
#include "core/errors/scene_error.h"
#include "tests/support/bsdf_checks.h"
#include "tests/support/chi2.h"
#include "tests/support/microfacet_oracle.h"
#include "tests/support/thrown_message.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using test::below;
using test::direction;
using test::kImportance;
using test::kRadiance;

std::shared_ptr<Bsdf> rough(const std::string& distribution, float alpha, float eta) {
  return test::make_bsdf("<bsdf type='roughdielectric'><string name='distribution' value='" + distribution +
                         "'/><float name='alpha' value='" + std::to_string(alpha) + "'/>" + test::ior_params(eta) +
                         "</bsdf>");
}

struct Config {
  std::string distribution;
  float alpha, eta;
};

std::vector<Config> configs() {
  std::vector<Config> out;
  for (const char* d : {"beckmann", "ggx"})
    for (float alpha : {0.05f, 0.3f, 0.8f})
      for (float eta : {1.5f, 1.33f}) out.push_back({d, alpha, eta});
  return out;
}

// Incident directions: from outside, and from inside below and beyond the
// critical angle (0.73 rad for 1.5, 0.85 for 1.33), down to 0.01 rad from grazing.
std::vector<Vec3> incident_directions() {
  return {direction(0.0f),        direction(0.8f),        direction(1.5607f),
          below(direction(0.4f)), below(direction(1.2f)), below(direction(1.5607f))};
}

// Chi-square tests in this file: 12 configurations x 6 directions, plus 2
// anisotropic ones x 2 directions (counted in kMaterialChi2Tests).
const double kAlpha = test::material_chi2_alpha();

void expect_consistent(const Bsdf& bsdf, Vec3 wo, const std::string& what) {
  for (const BsdfContext& ctx : {kRadiance, kImportance}) {
    const auto c = test::check_samples(bsdf, wo, ctx, 2000);
    EXPECT_GT(c.checked, 100) << what;
    EXPECT_LT(c.max_f_error, 1e-3) << what;
    EXPECT_LT(c.max_pdf_error, 1e-3) << what;
    EXPECT_EQ(c.non_finite, 0) << what;
  }
}

TEST(RoughDielectricBsdf, SamplesFollowThePdf) {
  for (const Config& config : configs()) {
    const auto bsdf = rough(config.distribution, config.alpha, config.eta);
    for (Vec3 wo : incident_directions()) {
      const std::string what = config.distribution + " alpha " + std::to_string(config.alpha) + " eta " +
                               std::to_string(config.eta) + " wo.z " + std::to_string(wo.z);
      // The pdf does not depend on the transport mode.
      // The sharpest lobes need finer bins for the quadrature of the pdf to converge.
      const int bins = config.alpha < 0.1f ? 2 : 1;
      const auto chi2 =
          test::chi2_bsdf(*bsdf, wo, kRadiance, {.sample_count = 100000, .bins_u = 20 * bins, .bins_v = 40 * bins});
      EXPECT_GT(chi2.p_value, kAlpha) << what << "\n" << chi2.report;
      expect_consistent(*bsdf, wo, what);
      EXPECT_LE(test::pdf_integral(*bsdf, wo, kRadiance), 1 + 1e-3) << what;
    }
  }
}

TEST(RoughDielectricBsdf, AnisotropicSamplesFollowThePdf) {
  for (const char* d : {"beckmann", "ggx"}) {
    const auto bsdf = test::make_bsdf(std::string("<bsdf type='roughdielectric'><string name='distribution' value='") +
                                      d + "'/><float name='alpha_u' value='0.1'/><float name='alpha_v' value='0.4'/>" +
                                      test::ior_params(1.5f) + "</bsdf>");
    for (Vec3 wo : {direction(0.9f, 1.0f), below(direction(0.5f, 2.0f))}) {
      const auto chi2 = test::chi2_bsdf(*bsdf, wo, kRadiance, {.sample_count = 100000, .bins_u = 20, .bins_v = 40});
      EXPECT_GT(chi2.p_value, kAlpha) << d << " wo.z " << wo.z << "\n" << chi2.report;
      expect_consistent(*bsdf, wo, d);
    }
  }
}

TEST(RoughDielectricBsdf, ReflectionIsReciprocalAndRefractionAdjoint) {
  for (const Config& config : configs()) {
    const auto bsdf = rough(config.distribution, config.alpha, config.eta);
    for (const BsdfContext& ctx : {kRadiance, kImportance})
      EXPECT_LT(test::reciprocity_error(*bsdf, ctx, 1000), 1e-4) << config.distribution << " " << config.alpha;
    test::UniformSource u(5);
    for (int k = 0; k < 1000; ++k) {
      const Vec3 wo = direction(std::acos(2 * u.next_1d() - 1), 6.2831853f * u.next_1d());
      const Vec3 wi = direction(std::acos(2 * u.next_1d() - 1), 6.2831853f * u.next_1d());
      if (wo.z * wi.z >= 0) continue;
      const Color rad = bsdf->eval(kRadiance, wo, wi), imp = bsdf->eval(kImportance, wo, wi);
      // The importance BTDF is the radiance one with the directions swapped
      // (the adjoint), and they differ by eta^2, eta = index at wi / at wo.
      const Color adj = bsdf->eval(kRadiance, wi, wo);
      const float eta = wo.z > 0 ? config.eta : 1 / config.eta;
      EXPECT_NEAR(imp.r, adj.r, 1e-4f * std::max(1.0f, imp.r));
      if (imp.r > 1e-6f) {
        EXPECT_NEAR(rad.r / imp.r, 1 / (eta * eta), 1e-4f);
        EXPECT_EQ(bsdf->pdf(kRadiance, wo, wi), bsdf->pdf(kImportance, wo, wi));
      }
    }
  }
}

TEST(RoughDielectricBsdf, SampledEtaAndModes) {
  const auto bsdf = rough("ggx", 0.3f, 1.5f);
  test::UniformSource u(9);
  int transmitted = 0;
  for (Vec3 wo : {direction(0.5f), below(direction(0.5f))})
    for (int k = 0; k < 2000; ++k) {
      const float u_lobe = u.next_1d();
      const Vec2 uv = u.next_2d();
      const auto r = bsdf->sample(kRadiance, wo, u_lobe, uv), i = bsdf->sample(kImportance, wo, u_lobe, uv);
      ASSERT_EQ(bool(r), bool(i));
      if (!r) continue;
      EXPECT_EQ(r->wi, i->wi);
      EXPECT_EQ(r->pdf, i->pdf);
      EXPECT_EQ(r->lobe, i->lobe);
      if (r->is_transmission()) {
        ++transmitted;
        EXPECT_EQ(r->lobe, kGlossyTransmission);
        EXPECT_LT(r->wi.z * wo.z, 0);
        EXPECT_FLOAT_EQ(r->eta, wo.z > 0 ? 1.5f : 1 / 1.5f);
        EXPECT_NEAR(r->f.r / i->f.r, 1 / (r->eta * r->eta), 1e-5f);
      } else {
        EXPECT_EQ(r->lobe, kGlossyReflection);
        EXPECT_GT(r->wi.z * wo.z, 0);
        EXPECT_EQ(r->eta, 1);
        EXPECT_EQ(r->f, i->f);
      }
    }
  EXPECT_GT(transmitted, 2000);
}

TEST(RoughDielectricBsdf, WhiteFurnace) {
  for (const Config& config : configs()) {
    const auto bsdf = rough(config.distribution, config.alpha, config.eta);
    for (Vec3 wo : incident_directions()) {
      // Single scattering loses energy to masking, never gains. (Beckmann's
      // weights are not bounded by 1, only their mean is: hence the error bar.)
      const auto a = test::albedo(*bsdf, wo, kImportance, 20000);
      const std::string what = config.distribution + " alpha " + std::to_string(config.alpha) + " eta " +
                               std::to_string(config.eta) + " wo.z " + std::to_string(wo.z);
      EXPECT_LE(a.mean.r, 1 + 4 * a.standard_error.r + 1e-5f) << what;
      // Little is lost away from grazing angles on smooth surfaces.
      if (std::abs(wo.z) > 0.1f && config.alpha < 0.1f) {
        EXPECT_GT(a.mean.r, 0.98f) << what;
      }
      EXPECT_GT(a.mean.r, 0.2f) << what;
      EXPECT_LE(bsdf->albedo(kImportance, wo).r, 1 + 1e-6f);
    }
  }
}

TEST(RoughDielectricBsdf, NearlySmoothMatchesDielectric) {
  for (const char* d : {"beckmann", "ggx"}) {
    const auto bsdf = rough(d, 1e-3f, 1.5f);
    const auto smooth = test::make_bsdf("<bsdf type='dielectric'>" + test::ior_params(1.5f) + "</bsdf>");
    for (Vec3 wo : {direction(0.0f), direction(1.0f), direction(1.5f), below(direction(0.5f))}) {
      expect_consistent(*bsdf, wo, d);
      for (const BsdfContext& ctx : {kRadiance, kImportance}) {
        const auto a = test::albedo(*bsdf, wo, ctx, 20000), s = test::albedo(*smooth, wo, ctx, 20000);
        EXPECT_NEAR(a.mean.r, s.mean.r, 0.01f + 4 * (a.standard_error.r + s.standard_error.r)) << d << " " << wo.z;
      }
      // Each lobe lands next to the smooth direction.
      const auto r = bsdf->sample(kImportance, wo, 0, {0.3f, 0.7f});
      const auto t = bsdf->sample(kImportance, wo, 0.9999f, {0.3f, 0.7f});
      const auto sr = smooth->sample(kImportance, wo, 0, {}), st = smooth->sample(kImportance, wo, 0.9999f, {});
      ASSERT_TRUE(r && t && sr && st);
      EXPECT_GT(dot(r->wi, sr->wi), 0.9999f);
      EXPECT_GT(dot(t->wi, st->wi), 0.9999f);
    }
  }
}

TEST(RoughDielectricBsdf, TotalInternalReflection) {
  // Far beyond the critical angle with smooth facets: every sample reflects.
  for (const char* d : {"beckmann", "ggx"}) {
    const auto bsdf = rough(d, 1e-3f, 1.5f);
    for (float theta : {1.0f, 1.3f}) {
      const Vec3 wo = below(direction(theta));
      test::UniformSource u(4);
      for (int k = 0; k < 1000; ++k) {
        const float u_lobe = u.next_1d();
        const auto s = bsdf->sample(kRadiance, wo, u_lobe, u.next_2d());
        if (!s) continue;
        EXPECT_EQ(s->lobe, kGlossyReflection);
        EXPECT_NEAR(s->f.r * std::abs(s->wi.z) / s->pdf, 1, 1e-2f);
      }
      const auto a = test::albedo(*bsdf, wo, kRadiance, 10000);
      EXPECT_NEAR(a.mean.r, 1, 1e-2f);
    }
  }
}

TEST(RoughDielectricBsdf, IndexMatchedPassesStraightThrough) {
  const auto bsdf = test::make_bsdf(
      "<bsdf type='roughdielectric'><float name='alpha' value='0.5'/><float name='int_ior' value='1.2'/>"
      "<float name='ext_ior' value='1.2'/></bsdf>");
  EXPECT_EQ(bsdf->lobes(), kDeltaTransmission);
  for (Vec3 wo : {direction(0.0f), direction(1.0f), below(direction(1.5607f))})
    for (const BsdfContext& ctx : {kRadiance, kImportance}) {
      const auto s = bsdf->sample(ctx, wo, 0.01f, {0.5f, 0.5f});
      ASSERT_TRUE(s);
      EXPECT_EQ(s->wi, -wo);
      EXPECT_EQ(s->lobe, kDeltaTransmission);
      EXPECT_EQ(s->pdf, 1);
      EXPECT_EQ(s->eta, 1);
      EXPECT_FLOAT_EQ(s->f.r * std::abs(s->wi.z) / s->pdf, 1);
      EXPECT_EQ(bsdf->eval(ctx, wo, -wo), Color());
      EXPECT_EQ(bsdf->pdf(ctx, wo, -wo), 0);
    }
}

// Finite at nearly smooth and very rough surfaces, indices near one and
// below one, and grazing angles from both sides; and the furnace, in both
// transport modes, equal to the albedo integrated over microfacet normals
// in the test (tests/support/microfacet_oracle; z-test at 1 %, Sidak-
// corrected over the 192 cases, plus the quadrature's error).
TEST(RoughDielectricBsdf, FiniteAtExtremes) {
  const double z_critical = test::two_sided_z_critical(test::sidak_alpha(0.01, 2 * 2 * 3 * 8 * 2));
  for (const char* d : {"beckmann", "ggx"})
    for (float alpha : {1e-3f, 1.0f})
      for (float eta : {1.5f, 1.0001f, 0.7f}) {
        const auto bsdf = rough(d, alpha, eta);
        const test::MicrofacetModel model{std::string(d) == "ggx", alpha, alpha};
        for (float z : {1.0f, 1e-2f, 1e-4f, 1e-7f, -1e-7f, -1e-4f, -1e-2f, -1.0f}) {
          const Vec3 wo = normalize(Vec3(std::sqrt(1 - z * z), 0, z));
          // From inside, the same interface seen upside down.
          const test::Interface interface { true, z > 0 ? eta : 1.0 / eta };
          const Vec3 up(wo.x, wo.y, std::abs(wo.z));
          const auto fine = test::microfacet_albedo(model, interface, up, 300);
          const auto coarse = test::microfacet_albedo(model, interface, up, 150);
          for (const BsdfContext& ctx : {kRadiance, kImportance}) {
            const auto c = test::check_samples(*bsdf, wo, ctx, 1000);
            EXPECT_EQ(c.non_finite, 0) << d << " " << alpha << " " << eta << " " << z;
            constexpr int kSamples = 10000;
            const auto a = test::albedo(*bsdf, wo, ctx, kSamples);
            const bool importance = ctx.mode == TransportMode::Importance;
            const double expected = importance ? fine.importance() : fine.radiance(interface.eta);
            const double error =
                std::abs(expected - (importance ? coarse.importance() : coarse.radiance(interface.eta))) + 1e-4;
            // A sample's weight lies in [0, w_max] (refraction in radiance
            // transport scales by 1 / eta^2), so its variance is at most
            // mu (w_max - mu) (Bhatia and Davis): rare losses, a masked
            // sample of weight 0, may be missing from the samples' own
            // spread (near eta 1 one sample in 5000 is lost).
            const double w_max = importance ? 1 : std::max(1.0, 1 / (interface.eta * interface.eta));
            const double se = std::max(double(a.standard_error.r),
                                       std::sqrt(std::max(0.0, expected * (w_max - expected)) / kSamples));
            EXPECT_NEAR(a.mean.r, expected, z_critical * se + error)
                << d << " " << alpha << " eta " << eta << " z " << z << (importance ? " importance" : " radiance")
                << ": quadrature error " << error;
          }
          test::UniformSource u(3);
          for (int k = 0; k < 200; ++k) {
            const Vec3 wi = direction(std::acos(2 * u.next_1d() - 1), 6.2831853f * u.next_1d());
            EXPECT_TRUE(bsdf->eval(kRadiance, wo, wi).is_finite());
            EXPECT_TRUE(std::isfinite(bsdf->pdf(kRadiance, wo, wi)));
          }
        }
        EXPECT_FALSE(bsdf->sample(kRadiance, Vec3(1, 0, 0), 0.5f, {0.5f, 0.5f}));
        EXPECT_EQ(bsdf->eval(kRadiance, Vec3(1, 0, 0), Vec3(0, 0, 1)), Color());
      }
}

TEST(RoughDielectricBsdf, BadParameters) {
  const auto error_of = [](const std::string& params) {
    return test::thrown_message<SceneError>(
        [&] { test::make_bsdf("<bsdf type='roughdielectric'>" + params + "</bsdf>"); });
  };
  EXPECT_THAT(error_of("<string name='distribution' value='phong'/>"), testing::HasSubstr("beckmann or ggx"));
  EXPECT_THAT(error_of("<float name='alpha_u' value='0.2'/>"), testing::HasSubstr("alpha_u and alpha_v"));
  EXPECT_THAT(error_of("<float name='alpha' value='0.2'/><float name='alpha_u' value='0.2'/>"
                       "<float name='alpha_v' value='0.2'/>"),
              testing::HasSubstr("not both"));
  EXPECT_THAT(error_of("<float name='alpha' value='-0.1'/>"), testing::HasSubstr("not negative"));
  EXPECT_EQ(error_of("<string name='distribution' value='ggx'/><float name='alpha_u' value='0.05'/>"
                     "<float name='alpha_v' value='0.3'/>"),
            "no error");
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// sample_visible = false draws facet normals from D(m) cos(theta_m) instead;
// sampling and pdf must still agree (2 chi-square tests, counted in
// kMaterialChi2Tests).
TEST(RoughDielectricBsdf, SamplingAllNormalsAgreesWithItsPdf) {
  const auto bsdf = test::make_bsdf(
      "<bsdf type='roughdielectric'><float name='alpha' value='0.3'/><boolean name='sample_visible' value='false'/>"
      "</bsdf>");
  for (float theta : {0.4f, 2.5f}) {  // from outside and from inside
    const Vec3 wo = test::direction(theta);
    const auto chi2 = test::chi2_bsdf(*bsdf, wo, {}, {.sample_count = 200000, .bins_u = 40, .bins_v = 80});
    EXPECT_GT(chi2.p_value, test::material_chi2_alpha()) << "theta " << theta << "\n" << chi2.report;
    const auto c = test::check_samples(*bsdf, wo, {}, 2000);
    EXPECT_GT(c.checked, 1000);
    EXPECT_LT(c.max_f_error, 1e-4);
    EXPECT_LT(c.max_pdf_error, 1e-4);
    EXPECT_EQ(c.non_finite, 0);
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
