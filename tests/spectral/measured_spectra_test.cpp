// Spectra a scene gives are kept as spectra in spectral mode:
//  - metamerism: inside a closed sphere emitting a band of 500-600 nm and
//    reflecting 0.9 below 540 nm and 0.05 above, one bounce (max_depth 2)
//    shows the colour of E (1 + rho), computed here by quadrature; RGB
//    transport, multiplying the two spectra's colours, would be far off.
//    Image means are z-tested per channel at 0.1%, Sidak-corrected over the
//    file's checks, seeds fixed;
//  - named metals' Fresnel reflectance at normal incidence from Johnson and
//    Christy's published n and k (at wavelengths they tabulate);
//  - the analysis: measured conductors and spectra RGB misrepresents turn
//    spectral transport on, smooth ones do not, media keep it off; bad
//    conductor spectra are refused.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "core/bsdf/conductor_data.h"
#include "core/bsdf/reflectance_at.h"
#include "core/color/spectrum_to_rgb.h"
#include "core/scene/scene.h"
#include "core/spectral/rgb_lift.h"
#include "tests/support/chi2.h"
#include "tests/support/image_mean.h"
#include "tests/support/test_scenes.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using ::testing::HasSubstr;

constexpr const char* kBand = "400:0, 499.9:0, 500:1, 600:1, 600.1:0, 700:0";
constexpr const char* kStep = "400:0.9, 539.9:0.9, 540:0.05, 700:0.05";

std::string furnace(const std::string& emission, const std::string& reflectance) {
  return "<scene version='3.0.0'><integrator type='path'><integer name='max_depth' value='2'/></integrator>"
         "<sensor type='perspective'><float name='fov' value='70'/><sampler type='independent'/>"
         "<transform name='to_world'><lookat origin='0, 0, 0' target='1, 0.3, 0.2'/></transform>"
         "<film type='hdrfilm'><integer name='width' value='16'/><integer name='height' value='16'/>"
         "<rfilter type='box'/></film></sensor>"
         "<shape type='sphere'><boolean name='flip_normals' value='true'/><bsdf type='diffuse'>" +
         reflectance + "</bsdf><emitter type='area'>" + emission + "</emitter></shape></scene>";
}

TEST(MeasuredSpectra, MetamersRenderAsTheirSpectraMultiply) {
  const auto scene = test::scene_from_xml(furnace(std::string("<spectrum name='radiance' value='") + kBand + "'/>",
                                                  std::string("<spectrum name='reflectance' value='") + kStep + "'/>"));
  ASSERT_TRUE(scene->features().spectral);
  EXPECT_THAT(describe(scene->features()), HasSubstr("given as a spectrum that RGB would misrepresent"));
  // E (1 + rho) at 0.1 nm steps, as a spectrum.
  SampledSpectrum seen, band, step;
  for (int i = 3600; i <= 8300; ++i) {
    const double nm = i / 10.0, e = nm >= 500 && nm <= 600 ? 1 : 0, rho = nm < 540 ? 0.9 : 0.05;
    seen.nm.push_back(nm);
    seen.values.push_back(e * (1 + rho));
    band.nm.push_back(nm);
    band.values.push_back(e);
    step.nm.push_back(nm);
    step.values.push_back(rho);
  }
  const Color expected = spectrum_to_rgb(seen);
  const Color rgb_product = spectrum_to_rgb(band) * (Color(1) + spectrum_to_rgb(step));
  const test::ImageMean m = test::image_mean(test::render_scene(scene, 64, 5));
  const double z = test::two_sided_z_critical(test::sidak_alpha(0.001, 3));
  for (int c = 0; c < 3; ++c) {
    const double mean = m.mean[c], standard_error = m.standard_error[c];
    EXPECT_LT(std::abs(mean - expected[c]), z * standard_error + 1e-4)
        << "channel " << c << ": " << mean << " +- " << standard_error << ", expected " << expected[c];
    // Multiplying the colours instead misses red by 5x and blue by 1.7x.
    if (c != 1) {
      EXPECT_GT(std::abs(rgb_product[c] - expected[c]), 3 * z * standard_error) << c;
    }
  }
}

TEST(MeasuredSpectra, NamedMetalsReflectByTheirPublishedIndices) {
  // Gold at three wavelengths Johnson and Christy tabulate: (n, k).
  const float nm[3] = {548.6f, 616.8f, 659.5f};
  const double n[3] = {0.43, 0.21, 0.14}, k[3] = {2.455, 3.272, 3.697};
  Wavelengths w;
  w.nm = {nm[0], nm[1], nm[2]};
  w.pdf = {1, 1, 1};
  BsdfContext ctx;
  ctx.wavelengths = &w;
  const auto gold = named_conductor("Au");
  ASSERT_TRUE(gold && gold->measured());
  const Color F = fresnel_conductor_at(ctx, 1, *gold);
  for (int i = 0; i < 3; ++i) {
    const double R = ((n[i] - 1) * (n[i] - 1) + k[i] * k[i]) / ((n[i] + 1) * (n[i] + 1) + k[i] * k[i]);
    EXPECT_NEAR(F[i], R, 1e-5) << nm[i] << " nm";
  }
  // Every named metal is measured over the whole range spectral mode samples.
  for (const std::string& name : conductor_names()) {
    const auto ior = named_conductor(name);
    ASSERT_TRUE(ior && ior->measured()) << name;
    EXPECT_LE(ior->eta_spectrum->nm.front(), kMinWavelengthNm) << name;
    EXPECT_GE(ior->eta_spectrum->nm.back(), kMaxWavelengthNm) << name;
  }
}

TEST(MeasuredSpectra, ReflectancesAreReadAtTheWavelengthsWithinOne) {
  auto spectrum = std::make_shared<SampledSpectrum>();
  spectrum->nm = {400, 500, 600};
  spectrum->values = {0.2, 0.6, 1.4};
  const ConstantTexture texture(Color(0.5f), spectrum);
  Wavelengths w;
  w.nm = {450, 550, 590};
  w.pdf = {1, 1, 1};
  BsdfContext ctx;
  ctx.wavelengths = &w;
  const Color c = reflectance_at(texture, ctx);
  EXPECT_NEAR(c.r, 0.4, 1e-6);
  EXPECT_NEAR(c.g, 1.0, 1e-6);  // 1.0 interpolated
  EXPECT_NEAR(c.b, 1.0, 1e-6);  // 1.32, clamped
  EXPECT_EQ(reflectance_at(texture, BsdfContext{}), Color(0.5f));
}

TEST(MeasuredSpectra, TheAnalysisWeighsWhatRgbWouldMisrepresent) {
  const std::string light = "<emitter type='point'><point name='position' x='0' y='3' z='0'/></emitter>";
  const auto with = [&](const std::string& bsdf, const std::string& extra = "") {
    return test::scene_from_xml("<scene version='3.0.0'>" + light + extra + "\n<shape type='sphere'>" + bsdf +
                                "</shape></scene>");
  };
  const auto smooth = with("<bsdf type='diffuse'><spectrum name='reflectance' value='400:0.5, 700:0.5'/></bsdf>");
  EXPECT_FALSE(smooth->features().spectral);
  EXPECT_LT(lift_misfit(SampledSpectrum{{400, 700}, {0.5, 0.5}}, false), 0.01);
  const auto step =
      with(std::string("<bsdf type='diffuse'><spectrum name='reflectance' value='") + kStep + "'/></bsdf>");
  EXPECT_TRUE(step->features().spectral);
  EXPECT_THAT(describe(step->features()),
              HasSubstr("test.xml:2: bsdf reflectance given as a spectrum that RGB would misrepresent"));
  const auto measured = with(
      "<bsdf type='conductor'><spectrum name='eta' value='400:1.5, 700:0.2'/><spectrum name='k' "
      "value='400:2, 700:4'/></bsdf>");
  EXPECT_TRUE(measured->features().spectral);
  EXPECT_THAT(describe(measured->features()),
              HasSubstr("a conductor whose index is measured: test.xml:2: bsdf eta given as a spectrum"));
  const auto named = with("<bsdf type='conductor'><string name='material' value='Au'/></bsdf>");
  EXPECT_FALSE(named->features().spectral);
  const auto in_fog = with(std::string("<bsdf type='diffuse'><spectrum name='reflectance' value='") + kStep +
                               "'/></bsdf><ref name='interior' id='fog'/>",
                           "<medium type='homogeneous' id='fog'/>");
  EXPECT_FALSE(in_fog->features().spectral);
  EXPECT_THAT(describe(in_fog->features()), HasSubstr("but its media are not rendered spectrally yet"));
  // An index-matched boundary alone takes the media's walk, which the
  // spectral check refuses as well.
  const auto behind_null =
      with(std::string("<bsdf type='diffuse'><spectrum name='reflectance' value='") + kStep + "'/></bsdf>",
           "<shape type='rectangle'><bsdf type='null'/></shape>");
  EXPECT_FALSE(behind_null->features().spectral);
  EXPECT_THAT(describe(behind_null->features()), HasSubstr("(nor index-matched null boundaries)"));
}

TEST(MeasuredSpectra, BadConductorSpectraAreRefused) {
  const auto error = [](const std::string& params) {
    return test::load_error("<scene version='3.0.0'>\n<shape type='sphere'><bsdf type='conductor'>" + params +
                            "</bsdf></shape></scene>");
  };
  EXPECT_THAT(error("<spectrum name='eta' value='400:1.5, 700:0.2'/><rgb name='k' value='3'/>"),
              HasSubstr("test.xml:2: parameter 'k' of bsdf 'conductor': give eta and k both as spectra, or neither"));
  EXPECT_THAT(error("<spectrum name='eta' value='400:1.5, 500:-0.2, 700:1'/><spectrum name='k' value='400:2, 700:4'/>"),
              HasSubstr("test.xml:2: <spectrum>: value -0.200000 at 500.000000 nm is negative"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
