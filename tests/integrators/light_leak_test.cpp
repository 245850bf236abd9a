// A light shut inside a closed box must leave the outside black. The box's
// walls have no thickness, a metal ball inside makes caustics (so photon
// traces its photons too), the light sits 1e-4 of the box's size from one
// wall, and the camera looks at the floor just outside that wall, where a
// shadow ray shortened by too large an offset, a light ray started on the
// wrong side, or a hit missed at the wall's edge would put light. Every
// integrator, at sizes from a millimetre to a hundred kilometres; the
// expected image is exactly zero, so one leaked path fails.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

std::string boxed_light(const std::string& integrator, double size) {
  const auto v = [size](double x) {
    char s[32];
    std::snprintf(s, sizeof s, "%.9g", x * size);
    return std::string(s);
  };
  const std::string light_x = v(1 - 0.02 - 1e-4);
  const bool photons = integrator == "photon" || integrator == "sppm";
  return "<scene version='3.0.0'><integrator type='" + integrator + "'>" +
         (photons ? "<integer name='photons' value='5000'/>" : "") +
         "</integrator><sensor type='perspective'><float name='fov' value='50'/>"
         "<transform name='to_world'><lookat origin='" +
         v(4) + ", " + v(0.5) + ", " + v(2) + "' target='" + v(1.3) + ", 0, " + v(-0.8) +
         "' up='0, 0, 1'/></transform>"
         "<film type='hdrfilm'><integer name='width' value='16'/><integer name='height' value='16'/></film></sensor>"
         "<shape type='cube'><transform name='to_world'><scale value='" +
         v(1) +
         "'/></transform><bsdf type='diffuse'/></shape>"
         "<shape type='rectangle'><transform name='to_world'><scale value='" +
         v(10) + "'/><translate z='" + v(-1.0001) +
         "'/></transform><bsdf type='diffuse'/></shape>"
         "<shape type='sphere'><point name='center' x='" +
         v(0.6) + "' y='0' z='" + v(-0.6) + "'/><float name='radius' value='" + v(0.3) +
         "'/><bsdf type='conductor'/></shape>"
         "<shape type='sphere'><point name='center' x='" +
         light_x + "' y='0' z='0'/><float name='radius' value='" + v(0.02) +
         "'/><emitter type='area'><rgb name='radiance' value='1000'/></emitter></shape></scene>";
}

TEST(LightLeak, AClosedBoxKeepsItsLightInAtEveryScale) {
  for (const char* integrator : {"path", "direct", "ptracer", "bdpt", "photon", "sppm"})
    for (const double size : {1e-3, 1.0, 1e3, 1e5}) {
      const auto scene = test::scene_from_xml(boxed_light(integrator, size));
      RenderStats stats;
      const FilmBuffer film = test::render_scene(scene, 16, 5, 0, &stats);
      EXPECT_THAT(stats.summary, testing::Not(testing::HasSubstr("skipped"))) << integrator;
      double sum = 0;
      for (float v : film.resolve()) sum += v;
      EXPECT_EQ(sum, 0.0) << integrator << " at size " << size;
      EXPECT_EQ(film.dropped_samples(), 0u) << integrator << " at size " << size;
    }
}

// The same scene without the box: the floor in view is lit, so the test
// above looks where leaked light would arrive.
TEST(LightLeak, WithoutTheBoxTheFloorIsLit) {
  std::string xml = boxed_light("path", 1.0);
  const auto cube = xml.find("<shape type='cube'>"), end = xml.find("</shape>", cube) + 8;
  xml.erase(cube, end - cube);
  const FilmBuffer film = test::render_scene(test::scene_from_xml(xml), 16, 5);
  double sum = 0;
  for (float v : film.resolve()) sum += v;
  EXPECT_GT(sum, 1.0);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
