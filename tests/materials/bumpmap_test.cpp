
#include <OpenImageIO/imageio.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "core/math/constants.h"
#include "tests/support/bsdf_checks.h"
#include "tests/support/scratch_dir.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

namespace fs = std::filesystem;
using test::direction;

// Chi-square tests in this file: 2 wrappers x 3 incident angles (counted in kMaterialChi2Tests).
const double kAlpha = test::material_chi2_alpha();

const char* kDiffuse = "<bsdf type='diffuse'><rgb name='reflectance' value='0.2, 0.5, 0.8'/></bsdf>";

// A 16 x 1 float image whose bilinear lookup is h(u) = u away from the borders.
fs::path ramp() {
  static const fs::path path = [] {
    const fs::path file = test::scratch_dir() / "bumpmap_ramp.exr";
    const int w = 16;
    std::vector<float> px;
    for (int i = 0; i < w; ++i) px.push_back((i + 0.5f) / w);
    auto out = OIIO::ImageOutput::create(file.string());
    EXPECT_TRUE(out && out->open(file.string(), OIIO::ImageSpec(w, 1, 1, OIIO::TypeDesc::FLOAT)));
    EXPECT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
    out->close();
    return file;
  }();
  return path;
}

std::string ramp_bump(float scale) {
  return "<bsdf type='bumpmap'><texture type='bitmap'><string name='filename' value='" + ramp().string() +
         "'/><string name='wrap_mode' value='clamp'/></texture><float name='scale' value='" + std::to_string(scale) +
         "'/>" + kDiffuse + "</bsdf>";
}

const BsdfContext kCentre{TransportMode::Radiance, {0.5f, 0.5f}};

TEST(BumpMapBsdf, ConstantHeightIsTheNestedBsdf) {
  const auto bump = test::make_bsdf(std::string("<bsdf type='bumpmap'><texture type='checkerboard'/>") +
                                    "<float name='scale' value='3'/>" + kDiffuse + "</bsdf>");
  const auto plain = test::make_bsdf(kDiffuse);
  const BsdfContext ctx{TransportMode::Radiance, {0.25f, 0.25f}};  // inside one check: flat
  for (float to : {0.0f, 0.6f, 1.4f})
    for (float ti : {0.1f, 0.9f, 1.55f}) {
      const Vec3 wo = direction(to, 0.4f), wi = direction(ti, 2.5f);
      EXPECT_EQ(bump->eval(ctx, wo, wi), plain->eval(ctx, wo, wi));
      EXPECT_EQ(bump->pdf(ctx, wo, wi), plain->pdf(ctx, wo, wi));
      const auto a = bump->sample(ctx, wo, 0.3f, {0.2f, 0.7f}), b = plain->sample(ctx, wo, 0.3f, {0.2f, 0.7f});
      ASSERT_TRUE(a && b);
      EXPECT_NEAR(a->wi.x, b->wi.x, 1e-6f);
      EXPECT_NEAR(a->wi.z, b->wi.z, 1e-6f);
      EXPECT_EQ(a->pdf, b->pdf);
    }
}

TEST(BumpMapBsdf, LinearRampTiltsTheNormal) {
  for (float scale : {0.5f, 1.0f, 2.0f}) {
    const auto bump = test::make_bsdf(ramp_bump(scale));
    // h = scale u over dp/du = x, dp/dv = y: n' = normalize(-scale, 0, 1), tilted by atan(scale) toward -x.
    const float tilt = std::atan(scale);
    const Vec3 n_p(-std::sin(tilt), 0, std::cos(tilt));
    const Vec3 wo = direction(0.3f, kPi);
    // The diffuse pdf is cos(wi, n') / pi.
    EXPECT_NEAR(bump->pdf(kCentre, wo, n_p), kInvPi, 1e-4f) << scale;
    EXPECT_NEAR(bump->pdf(kCentre, wo, Vec3(0, 0, 1)), std::cos(tilt) * kInvPi, 1e-4f) << scale;
    // Directions toward +x below the tilted plane (elevation < tilt) get nothing.
    const float eps = 0.02f;
    const Vec3 above(std::cos(tilt + eps), 0, std::sin(tilt + eps)),
        below(std::cos(tilt - eps), 0, std::sin(tilt - eps));
    EXPECT_GT(bump->eval(kCentre, wo, above).r, 0.0f) << scale;
    EXPECT_EQ(bump->eval(kCentre, wo, below), Color()) << scale;
    EXPECT_EQ(bump->pdf(kCentre, wo, below), 0.0f) << scale;
  }
  // Negative scale tilts the other way.
  const auto inverted = test::make_bsdf(ramp_bump(-1));
  EXPECT_NEAR(inverted->pdf(kCentre, direction(0.3f), normalize(Vec3(1, 0, 1))), kInvPi, 1e-4f);
}

TEST(BumpMapBsdf, FollowsTheTangents) {
  // Tangents twice as long along u halve the slope: n' = normalize(-1, 0, 2).
  const auto bump = test::make_bsdf(ramp_bump(1));
  BsdfContext ctx = kCentre;
  ctx.dpdu = {2, 0, 0};
  EXPECT_NEAR(bump->pdf(ctx, direction(0.3f), normalize(Vec3(-1, 0, 2))), kInvPi, 1e-4f);
  // A frame whose u runs along y: the tilt follows u.
  ctx.dpdu = {0, 1, 0};
  ctx.dpdv = {-1, 0, 0};
  EXPECT_NEAR(bump->pdf(ctx, direction(0.3f), normalize(Vec3(0, -1, 1))), kInvPi, 1e-4f);
}

TEST(NormalMapBsdf, FlatColourIsTheNestedBsdf) {
  const auto nmap = test::make_bsdf(std::string("<bsdf type='normalmap'><rgb name='normalmap' value='0.5, 0.5, 1'/>") +
                                    kDiffuse + "</bsdf>");
  const auto plain = test::make_bsdf(kDiffuse);
  for (float to : {0.0f, 0.6f, 1.4f})
    for (float ti : {0.1f, 0.9f, 1.55f}) {
      const Vec3 wo = direction(to, 0.4f), wi = direction(ti, 2.5f);
      EXPECT_EQ(nmap->eval(kCentre, wo, wi), plain->eval(kCentre, wo, wi));
      EXPECT_EQ(nmap->pdf(kCentre, wo, wi), plain->pdf(kCentre, wo, wi));
    }
}

TEST(NormalMapBsdf, DecodesTangentSpaceNormals) {
  // c = (n + 1) / 2 for n = normalize(1, 0, 1): tilted toward +u.
  const float h = 0.5f * std::sqrt(0.5f) + 0.5f;
  const auto nmap = test::make_bsdf("<bsdf type='normalmap'><rgb name='normalmap' value='" + std::to_string(h) +
                                    ", 0.5, " + std::to_string(h) + "'/>" + kDiffuse + "</bsdf>");
  EXPECT_NEAR(nmap->pdf(kCentre, direction(0.3f), normalize(Vec3(1, 0, 1))), kInvPi, 1e-4f);
  BsdfContext ctx = kCentre;
  ctx.dpdu = {0, 3, 0};  // u along y: the normal follows
  EXPECT_NEAR(nmap->pdf(ctx, direction(0.3f), normalize(Vec3(0, 1, 1))), kInvPi, 1e-4f);
  // A colour decoding below the surface leaves the normal alone.
  const auto bad = test::make_bsdf(std::string("<bsdf type='normalmap'><rgb name='normalmap' value='0.5, 0.5, 0'/>") +
                                   kDiffuse + "</bsdf>");
  EXPECT_NEAR(bad->pdf(kCentre, direction(0.3f), Vec3(0, 0, 1)), kInvPi, 1e-6f);
}

std::vector<std::pair<std::string, std::string>> wrappers() {
  const float h = 0.5f * std::sin(0.6f) + 0.5f, z = 0.5f * std::cos(0.6f) + 0.5f;
  return {{"bumpmap", ramp_bump(1.5f)},
          {"normalmap", "<bsdf type='normalmap'><rgb name='normalmap' value='" + std::to_string(h) + ", 0.5, " +
                            std::to_string(z) + "'/>" + kDiffuse + "</bsdf>"}};
}

TEST(PerturbedFrames, SamplesFollowThePdf) {
  for (const auto& [name, xml] : wrappers()) {
    const auto bsdf = test::make_bsdf(xml);
    for (float theta : {0.0f, 0.8f, 1.5f}) {
      // wo on the side the normals lean toward, so it stays above the perturbed surface.
      const Vec3 wo = name == "bumpmap" ? direction(theta, 2.9f) : direction(theta, 0.2f);
      const auto chi2 = test::chi2_bsdf(*bsdf, wo, kCentre, {.sample_count = 200000, .bins_u = 20, .bins_v = 40});
      EXPECT_GT(chi2.p_value, kAlpha) << name << " theta " << theta << "\n" << chi2.report;
      const auto c = test::check_samples(*bsdf, wo, kCentre, 4000);
      EXPECT_GT(c.checked, 1000) << name;
      EXPECT_LT(c.max_f_error, 1e-5) << name;
      EXPECT_LT(c.max_pdf_error, 1e-5) << name;
      EXPECT_EQ(c.non_finite, 0) << name;
    }
  }
}

TEST(PerturbedFrames, GrazingAnglesAndEnergy) {
  for (const auto& [name, xml] : wrappers()) {
    const auto bsdf = test::make_bsdf(xml);
    for (float theta : {0.0f, 0.7f, 1.3f, 1.55f, 1.5707f})
      for (float phi : {0.0f, 1.6f, 3.14f, 4.7f}) {
        const Vec3 wo = direction(theta, phi);
        const auto a = test::albedo(*bsdf, wo, kCentre, 20000);
        for (int c = 0; c < 3; ++c) {
          EXPECT_TRUE(std::isfinite(a.mean[c])) << name;
          EXPECT_LE(a.mean[c], Color(0.2f, 0.5f, 0.8f)[c] + 4 * a.standard_error[c] + 1e-6f)
              << name << " theta " << theta << " phi " << phi;
        }
        EXPECT_TRUE(bsdf->albedo(kCentre, wo).is_finite());
        for (float ti : {0.0f, 1.0f, 1.5707f, 1.5708f, 2.0f})
          for (float pi : {0.0f, 3.14f}) {
            const Vec3 wi = direction(ti, pi);
            EXPECT_TRUE(bsdf->eval(kCentre, wo, wi).is_finite()) << name;
            EXPECT_TRUE(std::isfinite(bsdf->pdf(kCentre, wo, wi))) << name;
          }
      }
    // Degenerate tangents do not produce NaN either.
    BsdfContext ctx = kCentre;
    ctx.dpdu = {0, 0, 0};
    ctx.dpdv = {0, 0, 0};
    EXPECT_TRUE(bsdf->eval(ctx, direction(0.5f), direction(0.7f, 2.0f)).is_finite()) << name;
    const auto s = bsdf->sample(ctx, direction(0.5f), 0.5f, {0.3f, 0.3f});
    if (s) {
      EXPECT_TRUE(s->f.is_finite() && std::isfinite(s->pdf)) << name;
    }
  }
}

TEST(PerturbedFrames, BadInput) {
  EXPECT_THAT(test::load_error(std::string("<scene version='3.0.0'><shape type='rectangle'><bsdf type='bumpmap'>") +
                               kDiffuse + "</bsdf></shape></scene>"),
              testing::HasSubstr("height texture"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><shape type='rectangle'><bsdf type='bumpmap'>"
                               "<texture type='checkerboard'/></bsdf></shape></scene>"),
              testing::HasSubstr("nested bsdf"));
  EXPECT_THAT(test::load_error(std::string("<scene version='3.0.0'><shape type='rectangle'><bsdf type='normalmap'>") +
                               kDiffuse + "</bsdf></shape></scene>"),
              testing::HasSubstr("normalmap"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
