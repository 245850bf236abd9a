// Hard cases of participating media, each rendered by path, ptracer and
// bdpt: every pixel finite, no sample dropped, and light where light must
// arrive.
//  - extinction 1e6 (a medium no light crosses) filling a glass sphere, and 0;
//  - media nested: a scattering medium inside glass inside another medium
//    (bounded by a null sphere) the camera sits in;
//  - a point light inside a medium;
//  - the camera inside a medium bounded by a null shape.

#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class MediumHardCases : public testing::TestWithParam<const char*> {
 protected:
  std::string box_scene(const std::string& media, const std::string& sensor_medium, const std::string& shapes,
                        const std::string& light) const {
    return "<scene version='3.0.0'><integrator type='" + std::string(GetParam()) + "'/>" + media +
           "<sensor type='perspective'><float name='fov' value='60'/>" + sensor_medium +
           "<transform name='to_world'><lookat origin='0, 0, 3' target='0, 0, 0'/></transform>"
           "<film type='hdrfilm'><integer name='width' value='16'/><integer name='height' value='16'/></film></sensor>"
           "<shape type='rectangle'><transform name='to_world'><scale value='5'/><translate z='-1.5'/></transform>"
           "</shape>" +
           shapes + light + "</scene>";
  }
};

const std::string kAreaLight =
    "<shape type='rectangle'><transform name='to_world'><rotate x='1' angle='90'/><translate y='1.8'/></transform>"
    "<emitter type='area'><rgb name='radiance' value='5'/></emitter></shape>";

std::string medium(const std::string& id, const std::string& sigma_t) {
  return "<medium type='homogeneous' id='" + id + "'><float name='sigma_t' value='" + sigma_t +
         "'/><float name='albedo' value='0.8'/></medium>";
}

// The image's mean, after checking every value finite and nothing dropped.
double finite_mean(const std::string& xml) {
  const auto scene = test::scene_from_xml(xml);
  RenderStats stats;
  const FilmBuffer film = test::render_scene(scene, 8, 1, 0, &stats);
  EXPECT_EQ(stats.dropped, 0u);
  double sum = 0;
  const auto img = film.resolve();
  for (float v : img) {
    EXPECT_TRUE(std::isfinite(v));
    sum += v;
  }
  return sum / img.size();
}

TEST_P(MediumHardCases, ExtremeExtinctionsInsideGlass) {
  for (const char* sigma : {"1e6", "0"}) {
    const double mean = finite_mean(
        box_scene(medium("m", sigma), "",
                  "<shape type='sphere'><bsdf type='dielectric'/><ref name='interior' id='m'/></shape>", kAreaLight));
    EXPECT_GT(mean, 0) << sigma;
  }
}

TEST_P(MediumHardCases, NestedMediaAroundTheCamera) {
  const double mean =
      finite_mean(box_scene(medium("outer", "0.3") + medium("inner", "4"), "<ref id='outer'/>",
                            "<shape type='sphere'><float name='radius' value='1.2'/><ref name='interior' id='outer'/>"
                            "</shape><shape type='sphere'><float name='radius' value='0.6'/><bsdf type='dielectric'/>"
                            "<ref name='interior' id='inner'/><ref name='exterior' id='outer'/></shape>",
                            kAreaLight));
  EXPECT_GT(mean, 0);
}

TEST_P(MediumHardCases, APointLightInsideAMedium) {
  // The camera looks into a fog ball lit only by a point at its centre.
  const double mean = finite_mean(
      box_scene(medium("fog", "2"), "", "<shape type='sphere'><ref name='interior' id='fog'/></shape>",
                "<emitter type='point'><point name='position' x='0' y='0' z='0'/><rgb name='intensity' value='10'/>"
                "<ref id='fog'/></emitter>"));
  EXPECT_GT(mean, 0);
}

TEST_P(MediumHardCases, TheCameraInsideABoundedMedium) {
  // A null sphere around the camera, the sensor in its medium.
  const double mean = finite_mean(
      box_scene(medium("fog", "0.5"), "<ref id='fog'/>",
                "<shape type='sphere'><point name='center' x='0' y='0' z='3'/><float name='radius' value='0.5'/>"
                "<ref name='interior' id='fog'/></shape>",
                kAreaLight));
  EXPECT_GT(mean, 0);
}

INSTANTIATE_TEST_SUITE_P(Integrators, MediumHardCases, testing::Values("path", "ptracer", "bdpt"),
                         test::scene_test_name);

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
