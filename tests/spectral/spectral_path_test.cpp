// path (and direct, ptracer and bdpt in the furnaces) in spectral mode against
// closed forms and against RGB mode:
//  - furnaces: inside a closed sphere that emits RGB white (D65, lifted)
//    and reflects diffusely with reflectance rho, every ray sees the
//    radiance Le / (1 - rho(l)) at each wavelength: grey 2 for rho = 0.5,
//    and for a coloured rho the colour of that spectrum, computed here by
//    1 nm quadrature through spectrum_to_rgb from the table's spectrum;
//  - a room with coloured walls under a white light, direct light only
//    (max_depth 2): RGB and spectral agree per region, since a reflectance
//    lifted and lit by D65 returns its RGB;
//  - what cannot be rendered spectrally yet is refused, each with its
//    message; `caustica info` says which mode the scene needs and why.
// Image means are z-tested per channel from the per-pixel variances, region
// means by a two-sample t-test over independent runs, at 0.1% Sidak-
// corrected over the file's checks; seeds are fixed.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "core/bsdf/bsdf.h"
#include "core/color/cie_tables.h"
#include "core/color/rgb_spectrum_table.h"
#include "core/color/spectrum_to_rgb.h"
#include "core/registry/properties.h"
#include "core/sampling/warp.h"
#include "core/scene/scene.h"
#include "tests/support/chi2.h"
#include "tests/support/image_mean.h"
#include "tests/support/independent_runs.h"
#include "tests/support/test_scenes.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using ::testing::HasSubstr;

constexpr int kChecks = 3 * 3 + 16 + 2 * 2;
const double kAlpha = test::sidak_alpha(0.001, kChecks);

void make_spectral(const LoadedScene& scene) {
  SceneFeatures f = scene->features();
  force_spectral(f, true);
  scene->set_features(f);
}

std::string furnace(const std::string& rho, const std::string& integrator = "path", int max_depth = -1) {
  std::string depth;
  if (max_depth >= 0) depth.append("<integer name='max_depth' value='").append(std::to_string(max_depth)).append("'/>");
  return "<scene version='3.0.0'><integrator type='" + integrator + "'>" + depth +
         "</integrator><sensor type='perspective'><float name='fov' value='70'/><sampler type='independent'/>"
         "<transform name='to_world'><lookat origin='0, 0, 0' target='1, 0.3, 0.2'/></transform>"
         "<film type='hdrfilm'><integer name='width' value='16'/><integer name='height' value='16'/>"
         "<rfilter type='box'/></film></sensor>"
         "<shape type='sphere'><boolean name='flip_normals' value='true'/><bsdf type='diffuse'><rgb "
         "name='reflectance' value='" +
         rho + "'/></bsdf><emitter type='area'><rgb name='radiance' value='1'/></emitter></shape></scene>";
}

void expect_image_mean(const LoadedScene& scene, Color expected, uint64_t seed, const std::string& what) {
  const test::ImageMean m = test::image_mean(test::render_scene(scene, 64, seed));
  for (int c = 0; c < 3; ++c) {
    const double mean = m.mean[c], standard_error = m.standard_error[c];
    EXPECT_LT(std::abs(mean - expected[c]), test::two_sided_z_critical(kAlpha) * standard_error + 1e-4)
        << what << ", channel " << c << ": " << mean << " +- " << standard_error << ", expected " << expected[c];
  }
}

// The colour of Le(l) / (1 - rho(l)), Le being D65 scaled to luminance 1,
// by 1 nm quadrature from the table's spectrum for rho.
Color coloured_furnace_radiance(std::array<float, 3> rho_rgb) {
  const SigmoidSpectrum rho = RgbSpectrumTable::built().lookup(rho_rgb);
  SampledSpectrum d65, radiance;
  for (int nm = kCieFirstNm; nm <= kCieLastNm; ++nm) {
    const double e = cie_table_at(kCieD65, nm);
    d65.nm.push_back(nm);
    d65.values.push_back(e);
    radiance.nm.push_back(nm);
    radiance.values.push_back(e / (1 - rho(nm)));
  }
  return spectrum_to_rgb(radiance) * (1 / spectrum_to_rgb(d65).luminance());
}

TEST(SpectralPath, GreyFurnaceHoldsTwo) {
  const auto scene = test::scene_from_xml(furnace("0.5"));
  make_spectral(scene);
  expect_image_mean(scene, Color(2), 1, "grey");
}

TEST(SpectralPath, DirectSeesOneBounceInTheFurnace) {
  // The emitter seen, plus its light reflected once: 1 + 0.5.
  const auto scene = test::scene_from_xml(furnace("0.5", "direct"));
  make_spectral(scene);
  expect_image_mean(scene, Color(1.5f), 7, "direct");
}

TEST(SpectralPath, ColouredFurnaceHoldsItsSpectrumsColour) {
  const auto scene = test::scene_from_xml(furnace("0.7, 0.3, 0.2"));
  make_spectral(scene);
  expect_image_mean(scene, coloured_furnace_radiance({0.7f, 0.3f, 0.2f}), 2, "coloured");
}

// Light tracing and bdpt in the same furnaces: their splats leave no
// per-pixel variance, so the image mean (over pixels and channels) comes
// from independent runs.
class SpectralLightPaths : public testing::TestWithParam<const char*> {};

TEST_P(SpectralLightPaths, FurnacesHoldTheirRadiance) {
  const auto expect_mean = [&](const std::string& rho, double expected, uint64_t seed, int max_depth = -1) {
    const auto scene = test::scene_from_xml(furnace(rho, GetParam(), max_depth));
    make_spectral(scene);
    const int runs = 8;
    uint64_t non_finite = 0;
    const auto e = test::estimate_regions(scene, {{{0, 0}, {16, 16}}}, 16, runs, seed, &non_finite)[0];
    EXPECT_EQ(non_finite, 0u);
    EXPECT_LT(std::abs(e.mean - expected), test::two_sided_t_critical(kAlpha, runs - 1) * e.standard_error + 1e-4)
        << GetParam() << ", reflectance " << rho << ": " << e.mean << " +- " << e.standard_error << ", expected "
        << expected;
  };
  expect_mean("0.5", 2, 50);
  const Color coloured = coloured_furnace_radiance({0.7f, 0.3f, 0.2f});
  expect_mean("0.7, 0.3, 0.2", (coloured.r + coloured.g + coloured.b) / 3, 60);
}

TEST(SpectralLightPaths, LightTracingSeesTheEmitterWhite) {
  // The emitter joined to the lens directly (max_depth 1) shows white. Its
  // splats' colour varies with their wavelengths: over 64 spp the image's
  // red-to-blue ratio spread by 0.02 across seeds, so a bound of 0.15 is
  // beyond 7 of those; a flat spectrum in D65's place would give
  // equal-energy's 1.33.
  const auto scene = test::scene_from_xml(furnace("0.5", "ptracer", 1));
  make_spectral(scene);
  const auto img = test::render_scene(scene, 64, 80).resolve();
  double sum[3] = {0, 0, 0};
  for (size_t i = 0; i < img.size(); ++i) sum[i % 3] += img[i];
  EXPECT_NEAR(sum[0] / sum[2], 1, 0.15);
  EXPECT_NEAR(sum[1] / sum[2], 1, 0.15);
}

INSTANTIATE_TEST_SUITE_P(Integrators, SpectralLightPaths, testing::Values("ptracer", "bdpt"), test::scene_test_name);

TEST(SpectralPath, DirectLightAgreesWithRgbUnderAWhiteLight) {
  const std::string xml =
      "<scene version='3.0.0'><integrator type='path'><integer name='max_depth' value='2'/></integrator>"
      "<sensor type='perspective'><float name='fov' value='60'/><sampler type='independent'/>"
      "<transform name='to_world'><lookat origin='0, 0, 3' target='0, 0, 0'/></transform>"
      "<film type='hdrfilm'><integer name='width' value='16'/><integer name='height' value='16'/></film></sensor>"
      "<shape type='rectangle'><transform name='to_world'><scale value='3'/><translate z='-1'/></transform>"
      "<bsdf type='diffuse'><rgb name='reflectance' value='0.63, 0.065, 0.05'/></bsdf></shape>"
      "<shape type='rectangle'><transform name='to_world'><scale value='0.8'/><translate x='-0.8' z='-0.5'/>"
      "</transform><bsdf type='diffuse'><rgb name='reflectance' value='0.14, 0.45, 0.091'/></bsdf></shape>"
      "<shape type='rectangle'><transform name='to_world'><rotate x='1' angle='90'/><translate y='1.5'/>"
      "</transform><emitter type='area'><rgb name='radiance' value='4'/></emitter></shape></scene>";
  const auto rgb = test::scene_from_xml(xml);
  const auto spectral = test::scene_from_xml(xml);
  make_spectral(spectral);
  const auto regions = test::grid_regions(16, 16, 4);
  const int runs = 10;
  const auto a = test::estimate_regions(rgb, regions, 64, runs, 10);
  const auto b = test::estimate_regions(spectral, regions, 64, runs, 30);
  const double t_critical = test::two_sided_t_critical(kAlpha, runs - 1);
  for (size_t i = 0; i < regions.size(); ++i)
    EXPECT_LT(std::abs(test::difference_score(b[i], a[i])), t_critical)
        << "region " << i << ": spectral " << b[i].mean << " +- " << b[i].standard_error << ", RGB " << a[i].mean
        << " +- " << a[i].standard_error;
}

// A material that has no spectral evaluation.
class RgbOnlyBsdf final : public Bsdf {
 public:
  explicit RgbOnlyBsdf(const Properties&) {}
  uint32_t lobes() const override { return kDiffuseReflection; }
  Color eval(const BsdfContext&, Vec3, Vec3) const override { return Color(0.1f); }
  float pdf(const BsdfContext&, Vec3, Vec3 wi) const override { return cosine_hemisphere_pdf(cos_theta(wi)); }
  std::optional<BsdfSample> sample(const BsdfContext&, Vec3, float, Vec2 u) const override {
    const Vec3 wi = square_to_cosine_hemisphere(u);
    return BsdfSample{wi, Color(0.1f), cosine_hemisphere_pdf(cos_theta(wi)), kDiffuseReflection, 1};
  }
  Color albedo(const BsdfContext&, Vec3) const override { return Color(0.3f); }
};
CAUSTICA_REGISTER_PLUGIN(RgbOnlyBsdf, "bsdf", "test_rgb_only", {}, {});

std::string render_error(const LoadedScene& scene) {
  try {
    test::render_scene(scene, 1);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "no error";
}

TEST(SpectralPath, WhatCannotBeRenderedSpectrallyIsRefused) {
  const auto rgb_only = test::scene_from_xml(
      "<scene version='3.0.0'><shape type='sphere'><bsdf type='test_rgb_only'/></shape>"
      "<shape type='rectangle'><bsdf type='twosided'><bsdf type='test_rgb_only'/></bsdf></shape>"
      "<emitter type='point'><point name='position' x='0' y='3' z='0'/></emitter></scene>",
      "rgb.xml");
  make_spectral(rgb_only);
  EXPECT_THAT(render_error(rgb_only), HasSubstr("rgb.xml: its materials test_rgb_only, twosided cannot be rendered "
                                                "with spectral transport (forced by the render settings) yet"));
  const auto fog = test::scene_from_xml(
      "<scene version='3.0.0'><medium type='homogeneous' id='m'/><shape type='sphere'><ref name='interior' "
      "id='m'/></shape><emitter type='point'><point name='position' x='0' y='3' z='0'/></emitter></scene>",
      "fog.xml");
  make_spectral(fog);
  EXPECT_THAT(render_error(fog), HasSubstr("fog.xml: participating media cannot be rendered with spectral transport"));
}

TEST(SpectralPath, TheAnalysisSaysWhichModeAndWhy) {
  const auto scene = test::scene_from_xml(furnace("0.5"));
  EXPECT_FALSE(scene->features().spectral);
  EXPECT_THAT(describe(scene->features()),
              HasSubstr("spectral transport: no, RGB (nothing in the scene needs it: no dispersive dielectric, "
                        "spectral emitter or measured conductor)"));
  RenderSettings settings;
  settings.transport = RenderSettings::Transport::Spectral;
  const RenderJob job(scene, settings);
  EXPECT_TRUE(job.scene()->features().spectral);
  EXPECT_THAT(describe(job.scene()->features()), HasSubstr("spectral transport: yes (forced by the render settings)"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
