// Every material in spectral mode against itself in RGB mode: with grey
// parameters a material's spectra are flat, so its spectral image must
// equal its RGB image in expectation. Each material (as a ball) sits in a
// closed sphere that emits RGB white and reflects diffusely; the two
// renders' image means per channel are compared by a two-sample z-test
// from the per-pixel variances at 0.1%, Sidak-corrected over the
// materials' channels; seeds are fixed. With coloured parameters, light
// that meets the material once (max_depth 2) under the white emitter still
// agrees with RGB (a lifted reflectance lit by D65 returns its RGB), which
// grey parameters cannot show: they lift to flat spectra whether lifted or
// not. A coloured conductor (gold) renders finite and keeps its hue.

#include <gtest/gtest.h>

#include <cmath>

#include "core/scene/scene.h"
#include "tests/support/chi2.h"
#include "tests/support/image_mean.h"
#include "tests/support/test_scenes.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

const char* const kMaterials[] = {
    "<bsdf type='dielectric'><float name='int_ior' value='1.5'/></bsdf>",
    "<bsdf type='thindielectric'/>",
    "<bsdf type='roughdielectric'><float name='alpha' value='0.3'/></bsdf>",
    "<bsdf type='conductor'><string name='material' value='none'/><float name='eta' value='1.5'/>"
    "<float name='k' value='3'/></bsdf>",
    "<bsdf type='roughconductor'><string name='material' value='none'/><float name='eta' value='0.5'/>"
    "<float name='k' value='2'/><float name='alpha' value='0.2'/></bsdf>",
    "<bsdf type='plastic'><rgb name='diffuse_reflectance' value='0.4'/></bsdf>",
    "<bsdf type='roughplastic'><rgb name='diffuse_reflectance' value='0.3'/></bsdf>",
    "<bsdf type='phong'/>",
    "<bsdf type='twosided'><bsdf type='diffuse'><rgb name='reflectance' value='0.6'/></bsdf></bsdf>",
    "<bsdf type='blendbsdf'><float name='weight' value='0.3'/><bsdf type='diffuse'/><bsdf type='conductor'/></bsdf>",
    "<bsdf type='mask'><float name='opacity' value='0.4'/><bsdf type='diffuse'/></bsdf>",
};
const char* const kColouredMaterials[] = {
    "<bsdf type='dielectric'><rgb name='specular_reflectance' value='0.9, 0.5, 0.2'/></bsdf>",
    "<bsdf type='conductor'><rgb name='specular_reflectance' value='0.2, 0.5, 0.9'/></bsdf>",
    "<bsdf type='roughconductor'><rgb name='specular_reflectance' value='0.8, 0.3, 0.6'/></bsdf>",
    "<bsdf type='plastic'><rgb name='diffuse_reflectance' value='0.1, 0.6, 0.3'/></bsdf>",
    "<bsdf type='roughplastic'><rgb name='diffuse_reflectance' value='0.7, 0.2, 0.1'/></bsdf>",
    "<bsdf type='phong'><rgb name='diffuse_reflectance' value='0.2, 0.3, 0.7'/></bsdf>",
};
const double kZCritical = test::two_sided_z_critical(
    test::sidak_alpha(0.001, 3 * int(std::size(kMaterials) + std::size(kColouredMaterials))));

std::string ball_in_furnace(const std::string& material, int max_depth = -1) {
  return "<scene version='3.0.0'><integrator type='path'><integer name='max_depth' value='" +
         std::to_string(max_depth) +
         "'/></integrator><sensor type='perspective'><float name='fov' value='50'/>"
         "<sampler type='independent'/>"
         "<transform name='to_world'><lookat origin='0, 0, 0' target='1, 0.1, 0'/></transform>"
         "<film type='hdrfilm'><integer name='width' value='16'/><integer name='height' value='16'/>"
         "<rfilter type='box'/></film></sensor>"
         "<shape type='sphere'><float name='radius' value='3'/><boolean name='flip_normals' value='true'/>"
         "<bsdf type='diffuse'/><emitter type='area'><rgb name='radiance' value='1'/></emitter></shape>"
         "<shape type='sphere'><point name='center' x='1.5' y='0' z='0'/><float name='radius' value='0.6'/>" +
         material + "</shape></scene>";
}

test::ImageMean image_mean(const LoadedScene& scene, uint64_t seed) {
  const test::ImageMean m = test::image_mean(test::render_scene(scene, 128, seed));
  EXPECT_EQ(m.non_finite, 0);
  return m;
}

LoadedScene spectral(const std::string& xml) {
  auto scene = test::scene_from_xml(xml);
  SceneFeatures f = scene->features();
  force_spectral(f, true);
  scene->set_features(f);
  return scene;
}

void expect_as_in_rgb(const std::string& xml, const std::string& what) {
  const test::ImageMean rgb = image_mean(test::scene_from_xml(xml), 3);
  const test::ImageMean spec = image_mean(spectral(xml), 4);
  for (int c = 0; c < 3; ++c) {
    const double se = std::hypot(rgb.standard_error[c], spec.standard_error[c]) + 1e-5 * rgb.mean[c];
    EXPECT_LT(std::abs(spec.mean[c] - rgb.mean[c]), kZCritical * se)
        << what << ", channel " << c << ": spectral " << spec.mean[c] << " +- " << spec.standard_error[c] << ", RGB "
        << rgb.mean[c] << " +- " << rgb.standard_error[c];
  }
}

std::string material_name(const testing::TestParamInfo<const char*>& info) {
  const std::string xml = info.param;
  const size_t start = xml.find("type='") + 6;
  return xml.substr(start, xml.find('\'', start) - start);
}

class SpectralMaterials : public testing::TestWithParam<const char*> {};

TEST_P(SpectralMaterials, GreyParametersRenderAsInRgb) { expect_as_in_rgb(ball_in_furnace(GetParam()), GetParam()); }

INSTANTIATE_TEST_SUITE_P(Materials, SpectralMaterials, testing::ValuesIn(kMaterials), material_name);

class ColouredSpectralMaterials : public testing::TestWithParam<const char*> {};

TEST_P(ColouredSpectralMaterials, OneBounceUnderWhiteRendersAsInRgb) {
  expect_as_in_rgb(ball_in_furnace(GetParam(), 2), GetParam());
}

INSTANTIATE_TEST_SUITE_P(Materials, ColouredSpectralMaterials, testing::ValuesIn(kColouredMaterials), material_name);

TEST(SpectralMaterials, GoldKeepsItsHue) {
  const test::ImageMean gold =
      image_mean(spectral(ball_in_furnace("<bsdf type='conductor'><string name='material' value='Au'/></bsdf>")), 5);
  EXPECT_GT(gold.mean[0], gold.mean[2]);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
