// Light transport has no length scale: a scene as small or as large as
// caustica traces (1e-7 to 1e8 across, core/scene/scene_extent.h) renders
// the image it renders at unit size, its shapes placed by scaling
// transforms. Each integrator's region means at each scale against its own at unit
// size, by independent runs at 0.1 %, Sidak-corrected over the regions,
// scales and integrators, Student's t; seeds fixed. Scenes beyond those
// sizes are refused, saying why.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "tests/support/chi2.h"
#include "tests/support/independent_runs.h"
#include "tests/support/test_scenes.h"
#include "tests/support/thrown_message.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using testing::HasSubstr;

constexpr int kRuns = 8;

// A ball on a floor lit by a glowing ball, seen from above, every length
// (the clipping planes' too) times `size`; shapes placed by scaling
// transforms, so their normals pass through the inverse scale.
std::string scene_xml(const std::string& integrator, double size) {
  const auto v = [size](double x) {
    char s[32];
    std::snprintf(s, sizeof s, "%.9g", x * size);
    return std::string(s);
  };
  return "<scene version='3.0.0'><integrator type='" + integrator +
         "'><integer name='max_depth' value='4'/></integrator>"
         "<sensor type='perspective'><float name='fov' value='45'/><float name='near_clip' value='" +
         v(0.01) + "'/><float name='far_clip' value='" + v(100) + "'/><transform name='to_world'><lookat origin='0, " +
         v(-1.5) + ", " + v(2.5) +
         "' target='0, 0, 0' up='0, 0, 1'/></transform><film type='hdrfilm'><integer name='width' value='16'/>"
         "<integer name='height' value='16'/><rfilter type='box'/></film></sensor>"
         "<shape type='rectangle'><transform name='to_world'><scale value='" +
         v(2) +
         "'/></transform></shape>"
         "<shape type='sphere'><transform name='to_world'><scale value='" +
         v(0.3) + "'/><translate z='" + v(0.3) +
         "'/></transform></shape>"
         "<shape type='sphere'><transform name='to_world'><scale value='" +
         v(0.1) + "'/><translate x='" + v(0.5) + "' y='" + v(-0.3) + "' z='" + v(1.2) +
         "'/></transform><emitter type='area'><rgb name='radiance' value='20'/></emitter></shape></scene>";
}

TEST(ScaleInvariance, TinyAndHugeScenesRenderAsAtUnitSize) {
  const auto regions = test::grid_regions(16, 16, 2);
  const std::vector<const char*> integrators = {"path", "bdpt", "ptracer"};
  // The scene spans 5.78 times `size` and reaches 3.5 times it from the
  // camera: 1e-7 across at the first, 1e8 from the camera at the second.
  const std::vector<double> sizes = {1.74e-8, 2.85e7};
  const double t_critical = test::two_sided_t_critical(
      test::sidak_alpha(0.001, int(regions.size() * integrators.size() * sizes.size())), kRuns - 1);
  for (const char* integrator : integrators) {
    const auto unit = test::estimate_regions(test::scene_from_xml(scene_xml(integrator, 1)), regions, 32, kRuns, 10);
    for (const double size : sizes) {
      const LoadedScene scene = test::scene_from_xml(scene_xml(integrator, size));
      const auto scaled = test::estimate_regions(scene, regions, 32, kRuns, 50);
      for (size_t r = 0; r < regions.size(); ++r)
        EXPECT_LT(std::abs(test::difference_score(scaled[r], unit[r])), t_critical)
            << integrator << " at size " << size << ", region " << r << ": " << scaled[r].mean << " +- "
            << scaled[r].standard_error << " against " << unit[r].mean << " +- " << unit[r].standard_error;
      EXPECT_GT(scaled[0].mean, 0) << integrator << " at size " << size;
    }
  }
}

std::string load_error(const std::string& xml) {
  return test::thrown_message<std::exception>([&] { test::scene_from_xml(xml, "scale.xml"); });
}

TEST(ScaleInvariance, ScenesTooSmallOrTooFarAreRefused) {
  EXPECT_THAT(load_error(scene_xml("path", 1e-30)),
              HasSubstr("scale.xml:1: the shapes span only 5.78e-30, and caustica traces scenes at least 1e-07 "
                        "across in single precision: scale the scene up (its units are free)"));
  EXPECT_THAT(load_error(scene_xml("path", 1e10)),
              HasSubstr("scale.xml:1: the shapes reach 3.5e+10 from the camera, and caustica traces only within "
                        "1e+08 of it in single precision: scale the scene down (its units are free)"));
  // A small scene seen from afar is as far as a large one.
  EXPECT_THAT(load_error("<scene version='3.0.0'><sensor type='perspective'><transform name='to_world'><lookat "
                         "origin='0, 0, 2e8' target='0, 0, 0' up='0, 1, 0'/></transform></sensor>"
                         "<shape type='sphere'/></scene>"),
              HasSubstr("the shapes reach 2e+08 from the camera"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
