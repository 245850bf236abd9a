// Dispersive dielectrics: a bounce refracts by the index at the hero
// wavelength (Snell's law with the Sellmeier index of N-SF11, computed here
// from Schott's coefficients), the d-line index in RGB mode (Schott's
// n_d = 1.78472); the scene analysis turns spectral transport on for them;
// terminating the secondary wavelengths weighs the hero three times in the
// conversion to XYZ; and a dispersive ball in the furnace (a closed sphere
// emitting RGB white, reflectance 0.5: radiance 2 outside the ball at every
// wavelength) leaves the image at 2 for path, ptracer and bdpt, z- and
// t-tested at 0.1%, Sidak-corrected over the file's checks, fixed seeds.
// Bad dispersion parameters each give their message.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "core/color/cie_tables.h"
#include "core/scene/scene.h"
#include "core/spectral/wavelengths.h"
#include "tests/support/bsdf_checks.h"
#include "tests/support/chi2.h"
#include "tests/support/command.h"
#include "tests/support/independent_runs.h"
#include "tests/support/test_scenes.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using ::testing::HasSubstr;
using ::testing::Not;

constexpr const char* kSf11Glass =
    "<bsdf type='dielectric'><string name='dispersion' value='sf11'/><string name='ext_ior' value='vacuum'/></bsdf>";

// N-SF11's index from Schott's Sellmeier coefficients.
double sf11_index(double nm) {
  const double l2 = nm * nm * 1e-6;
  return std::sqrt(1 + 1.73759695 * l2 / (l2 - 0.013188707) + 0.313747346 * l2 / (l2 - 0.0623068142) +
                   1.89878101 * l2 / (l2 - 155.23629));
}

Wavelengths with_hero(float nm) {
  Wavelengths w;
  w.nm = {nm, 550, 650};
  w.pdf = {1, 1, 1};
  return w;
}

double sin_theta(Vec3 w) { return std::sqrt(std::max(0.0, 1.0 - double(w.z) * double(w.z))); }

TEST(DispersiveDielectric, SmoothGlassRefractsByTheHerosIndex) {
  const auto glass = test::make_bsdf(kSf11Glass);
  EXPECT_TRUE(glass->disperses());
  const Vec3 wo = test::direction(0.7f);
  for (float nm : {420.0f, 530.0f, 680.0f}) {
    const Wavelengths w = with_hero(nm);
    BsdfContext ctx;
    ctx.wavelengths = &w;
    const auto bs = glass->sample(ctx, wo, 0.999f, {0.5f, 0.5f});
    ASSERT_TRUE(bs && bs->is_transmission()) << nm;
    const double n = sf11_index(nm);
    EXPECT_NEAR(sin_theta(bs->wi), sin_theta(wo) / n, 1e-5) << nm << " nm";
    EXPECT_NEAR(bs->eta, n, 1e-5) << nm << " nm";
  }
  const auto rgb = glass->sample(test::kRadiance, wo, 0.999f, {0.5f, 0.5f});
  ASSERT_TRUE(rgb && rgb->is_transmission());
  EXPECT_NEAR(sin_theta(rgb->wi), sin_theta(wo) / 1.78472, 1e-5);
}

TEST(DispersiveDielectric, RoughGlassRefractsAroundTheHerosDirection) {
  const auto glass = test::make_bsdf(
      "<bsdf type='roughdielectric'><float name='alpha' value='0.01'/><string name='dispersion' value='sf11'/>"
      "<string name='ext_ior' value='vacuum'/></bsdf>");
  EXPECT_TRUE(glass->disperses());
  const Vec3 wo = test::direction(0.7f);
  for (float nm : {420.0f, 680.0f}) {
    const Wavelengths w = with_hero(nm);
    BsdfContext ctx;
    ctx.wavelengths = &w;
    const auto consistency = test::check_samples(*glass, wo, ctx, 2000);
    EXPECT_GT(consistency.checked, 1000);
    EXPECT_LT(consistency.max_f_error, 1e-3) << nm;
    EXPECT_LT(consistency.max_pdf_error, 1e-3) << nm;
    // At alpha 0.01 the refracted directions stay within about 0.01 of the
    // smooth refraction, while the two wavelengths' refractions differ by 0.011.
    double sum = 0;
    int transmitted = 0;
    for (int i = 0; i < 1000; ++i) {
      const auto bs = glass->sample(ctx, wo, 0.999f, {(float(i) + 0.5f) / 1000, float((i * 37) % 1000) / 1000});
      if (!bs || !bs->is_transmission()) continue;
      sum += sin_theta(bs->wi);
      ++transmitted;
    }
    ASSERT_GT(transmitted, 900);
    EXPECT_NEAR(sum / transmitted, sin_theta(wo) / sf11_index(nm), 0.002) << nm << " nm";
  }
}

TEST(DispersiveDielectric, WrappersAndTheAnalysisSeeDispersion) {
  EXPECT_FALSE(test::make_bsdf("<bsdf type='dielectric'/>")->disperses());
  EXPECT_TRUE(
      test::make_bsdf(std::string("<bsdf type='mask'><float name='opacity' value='0.5'/>") + kSf11Glass + "</bsdf>")
          ->disperses());
  const std::string scene_start =
      "<scene version='3.0.0'><emitter type='point'><point name='position' x='0' y='3' z='0'/></emitter>"
      "<shape type='sphere'>";
  const auto dispersive = test::scene_from_xml(scene_start + kSf11Glass + "</shape></scene>");
  EXPECT_TRUE(dispersive->features().spectral);
  EXPECT_THAT(describe(dispersive->features()), HasSubstr("spectral transport: yes (a dispersive dielectric: sphere)"));
  const auto plain = test::scene_from_xml(scene_start + "<bsdf type='dielectric'/></shape></scene>");
  EXPECT_FALSE(plain->features().spectral);
}

TEST(DispersiveDielectric, TheSceneFileMayForceEitherMode) {
  const auto scene = [](const std::string& mode, const std::string& bsdf) {
    return "<scene version='3.0.0' spectral='" + mode +
           "'>\n<emitter type='point'><point name='position' x='0' y='3' z='0'/></emitter><shape type='sphere'>" +
           bsdf + "</shape></scene>";
  };
  const auto off = test::scene_from_xml(scene("off", kSf11Glass));
  EXPECT_FALSE(off->features().spectral);
  EXPECT_THAT(describe(off->features()), HasSubstr("spectral transport: no, RGB (forced by the scene file)"));
  const auto on = test::scene_from_xml(scene("on", "<bsdf type='diffuse'/>"));
  EXPECT_TRUE(on->features().spectral);
  EXPECT_TRUE(test::scene_from_xml(scene("auto", kSf11Glass))->features().spectral);
  // The command line overrides the file.
  RenderSettings settings;
  settings.transport = RenderSettings::Transport::Spectral;
  EXPECT_TRUE(RenderJob(off, settings).scene()->features().spectral);
  EXPECT_THAT(test::load_error(scene("maybe", "<bsdf type='diffuse'/>")),
              HasSubstr("test.xml:1: <scene spectral='maybe'> must be on, off or auto"));
}

TEST(DispersiveDielectric, ShippedSpectralScenesRenderSpectrally) {
  for (const char* name : {"prism", "cornell-box-diamond", "cornell-box-spectral"}) {
    const LoadedScene scene =
        load_scene(std::string(CAUSTICA_SOURCE_DIR) + "/scenes/" + name + ".xml", {{"res", "8"}, {"spp", "2"}});
    EXPECT_TRUE(scene->features().spectral) << name;
    RenderStats stats;
    test::render_scene(scene, 2, 1, 0, &stats);
    EXPECT_EQ(stats.dropped, 0u) << name;
  }
}

TEST(DispersiveDielectric, TheRenderLogSaysWhichModeAndWhy) {
  const std::string out = (std::filesystem::temp_directory_path() / "caustica_prism_log.exr").string();
  const auto spectral = test::run_caustica("render " + std::string(CAUSTICA_SOURCE_DIR) +
                                           "/scenes/prism.xml -D res=8 -D spp=1 -o " + out);
  EXPECT_EQ(spectral.status, 0) << spectral.output;
  EXPECT_THAT(spectral.output, HasSubstr("spectral transport: yes (a dispersive dielectric: obj)"));
  const auto forced = test::run_caustica("render " + std::string(CAUSTICA_SOURCE_DIR) +
                                         "/scenes/prism.xml -D res=8 -D spp=1 --spectral off -o " + out);
  EXPECT_THAT(forced.output, HasSubstr("spectral transport: no, RGB (forced by the render settings)"));
  const auto rgb = test::run_caustica("render " + std::string(CAUSTICA_SOURCE_DIR) +
                                      "/scenes/cornell-box.xml -D res=8 -D spp=1 -o " + out);
  EXPECT_THAT(rgb.output, Not(HasSubstr("spectral transport")));
}

TEST(DispersiveDielectric, BadDispersionsAreRefused) {
  const auto error = [](const std::string& params) {
    return test::load_error("<scene version='3.0.0'>\n<shape type='sphere'><bsdf type='dielectric'>" + params +
                            "</bsdf></shape></scene>");
  };
  EXPECT_THAT(error("<float name='int_ior' value='1.5'/><string name='dispersion' value='bk7'/>"),
              HasSubstr("test.xml:2: parameter 'dispersion' of bsdf 'dielectric': give either int_ior or a "
                        "dispersion, not both"));
  EXPECT_THAT(error("<string name='dispersion' value='flint'/>"),
              HasSubstr("no dispersive material is named 'flint' (known: bk7, fused silica, diamond, water, sf11)"));
  EXPECT_THAT(error("<string name='dispersion' value='sellmeier: 1, 0.01, 2'/>"),
              HasSubstr("Sellmeier's model takes pairs B, C (3 numbers given)"));
  EXPECT_THAT(error("<string name='dispersion' value='cauchy: -1.5'/>"),
              HasSubstr("its index at 360 nm is -1.500000, not a positive number"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><shape type='sphere'><bsdf type='thindielectric'>"
                               "<string name='dispersion' value='bk7'/></bsdf></shape></scene>"),
              HasSubstr("dispersion"));
}

// The y integral of the CIE tables by the trapezoid rule, as the
// conversion normalises.
double y_integral() {
  double sum = 0;
  for (size_t k = 0; k + 1 < size_t(kCieSamples); ++k) sum += 0.5 * (kCieY[k] + kCieY[k + 1]) * kCieStepNm;
  return sum;
}

TEST(DispersiveDielectric, TerminatedSecondariesLeaveTheHeroWeighedThreeTimes) {
  Wavelengths w = with_hero(500);
  w.pdf = {0.004f, 0.002f, 0.003f};
  terminate_secondaries(w);
  EXPECT_TRUE(secondaries_terminated(w));
  terminate_secondaries(w);  // once only
  const Color values(0.8f, 5.0f, 7.0f);
  const auto xyz = spectral_to_xyz(values, w);
  // The hero alone: value x (x, y, z)(500 nm) / pdf, over the y integral.
  const double scale = 0.8 / 0.004 / y_integral();
  const size_t i500 = size_t((500 - kCieFirstNm) / kCieStepNm);
  EXPECT_NEAR(xyz[0], scale * kCieX[i500], 1e-4 * std::abs(xyz[0]));
  EXPECT_NEAR(xyz[1], scale * kCieY[i500], 1e-4 * xyz[1]);
  EXPECT_NEAR(xyz[2], scale * kCieZ[i500], 1e-4 * xyz[2]);
  EXPECT_EQ(hero_only(values), Color(0.8f, 0, 0));
}

std::string dispersive_furnace(const std::string& integrator, const std::string& glass) {
  const bool photons = integrator == "sppm" || integrator == "photon";
  return "<scene version='3.0.0'><integrator type='" + integrator + "'>" +
         (photons ? "<integer name='photons' value='10000'/>" : "") +
         "</integrator><sensor type='perspective'><float name='fov' value='50'/><sampler type='independent'/>"
         "<transform name='to_world'><lookat origin='0, 0, 0' target='1, 0.1, 0'/></transform>"
         "<film type='hdrfilm'><integer name='width' value='16'/><integer name='height' value='16'/>"
         "<rfilter type='box'/></film></sensor>"
         "<shape type='sphere'><float name='radius' value='3'/><boolean name='flip_normals' value='true'/>"
         "<bsdf type='diffuse'><rgb name='reflectance' value='0.5'/></bsdf>"
         "<emitter type='area'><rgb name='radiance' value='1'/></emitter></shape>"
         "<shape type='sphere'><point name='center' x='1.5' y='0' z='0'/><float name='radius' value='0.6'/>" +
         glass + "</shape></scene>";
}

struct FurnaceCase {
  const char* integrator;
  const char* glass;
};

// Nearly smooth, so that the energy single-scattering microfacets lose
// stays far below the test's resolution.
constexpr const char* kRoughSf11 =
    "<bsdf type='roughdielectric'><float name='alpha' value='0.01'/><string name='dispersion' value='sf11'/></bsdf>";
const FurnaceCase kFurnaces[] = {{"path", kSf11Glass},  {"path", kRoughSf11},    {"bdpt", kSf11Glass},
                                 {"bdpt", kRoughSf11},  {"ptracer", kSf11Glass}, {"sppm", kSf11Glass},
                                 {"photon", kSf11Glass}};

class DispersiveFurnace : public testing::TestWithParam<FurnaceCase> {};

TEST_P(DispersiveFurnace, HoldsTwo) {
  const auto scene = test::scene_from_xml(dispersive_furnace(GetParam().integrator, GetParam().glass));
  ASSERT_TRUE(scene->features().spectral);
  const int runs = 8;
  uint64_t non_finite = 0;
  // Light tracing cannot see the ball; it sees the wall beyond, lit through the ball too.
  const bool light_tracing = std::string(GetParam().integrator) == "ptracer";
  const test::Region region = light_tracing ? test::Region{{0, 0}, {3, 3}} : test::Region{{0, 0}, {16, 16}};
  ASSERT_FALSE(light_tracing && test::seen_through_delta(*scene, region));
  const auto e = test::estimate_regions(scene, {region}, 16, runs, 40, &non_finite)[0];
  EXPECT_EQ(non_finite, 0u);
  const double alpha = test::sidak_alpha(0.001, int(std::size(kFurnaces)));
  EXPECT_LT(std::abs(e.mean - 2), test::two_sided_t_critical(alpha, runs - 1) * e.standard_error + 1e-4)
      << e.mean << " +- " << e.standard_error;
}

INSTANTIATE_TEST_SUITE_P(Integrators, DispersiveFurnace, testing::ValuesIn(kFurnaces),
                         [](const testing::TestParamInfo<FurnaceCase>& info) {
                           return std::string(info.param.integrator) +
                                  (std::string(info.param.glass).find("rough") != std::string::npos ? "_rough"
                                                                                                    : "_smooth");
                         });

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
