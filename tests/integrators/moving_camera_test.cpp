// A camera that moves over the shutter, seen by every integrator that
// follows a time: camera rays (path) and light paths joined to the moving
// lens (ptracer, bdpt). The oracles are still scenes the test writes
// itself: a camera carried along with the whole scene sees it still, and a
// camera that pans sees the mean of still cameras along its turn.
// Region means of independent runs are compared at 0.1 %, Sidak-corrected
// over the regions and comparisons, Student's t; seeds are fixed.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/scene/scene_features.h"
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
const std::string kLook = "<lookat origin='0, -1.5, 1.5' target='0, 0, 0.2' up='0, 0, 1'/>";

std::string sensor(const std::string& placement) {
  return "<sensor type='perspective'><float name='fov' value='40'/><float name='shutter_close' value='1'/>" +
         placement +
         "<film type='hdrfilm'><integer name='width' value='24'/><integer name='height' value='24'/>"
         "<rfilter type='box'/></film></sensor>";
}

std::string to_world(const std::string& inside) { return "<transform name='to_world'>" + inside + "</transform>"; }

std::string keyed(const std::vector<std::string>& keys) {
  std::string out = "<animation name='to_world'>";
  for (size_t k = 0; k < keys.size(); ++k)
    out += "<transform time='" + std::to_string(double(k) / double(keys.size() - 1)) + "'>" + keys[k] + "</transform>";
  return out + "</animation>";
}

std::string integrator(const std::string& name) {
  return "<integrator type='" + name + "'><integer name='max_depth' value='3'/></integrator>";
}

// A floor and a ball under a sun, each placed by `floor` and `ball` (the
// ball is of radius 0.3 about its own origin).
std::string sunlit(const std::string& name, const std::string& camera, const std::string& floor,
                   const std::string& ball) {
  return "<scene version='3.0.0'>" + integrator(name) + sensor(camera) +
         "<emitter type='directional'><vector name='direction' value='-0.3, 0.4, -1'/>"
         "<rgb name='irradiance' value='2'/></emitter><shape type='rectangle'>" +
         floor + "</shape><shape type='sphere'><float name='radius' value='0.3'/>" + ball + "</shape></scene>";
}

void expect_agree(const std::vector<test::RegionEstimate>& a, const std::vector<test::RegionEstimate>& b,
                  double t_critical, const std::string& what) {
  double total = 0;
  for (size_t r = 0; r < a.size(); ++r) {
    EXPECT_LT(std::abs(test::difference_score(a[r], b[r])), t_critical)
        << what << " region " << r << ": " << a[r].mean << " +- " << a[r].standard_error << " against " << b[r].mean
        << " +- " << b[r].standard_error;
    total += a[r].mean;
  }
  EXPECT_GT(total, 0) << what;
}

// Camera, floor and ball slide together by (1.2, 0.4, 0.1) under a sun,
// which no translation changes: the still scene's image.
TEST(MovingCamera, CarriedWithTheSceneItSeesItStill) {
  const std::string shift = "<translate x='1.2' y='0.4' z='0.1'/>";
  const std::string floor = "<scale value='3'/>", ball = "<translate x='0.2' z='0.3'/>";
  const auto regions = test::grid_regions(24, 24, 4);
  const double t_critical = test::two_sided_t_critical(test::sidak_alpha(0.001, 3 * int(regions.size())), kRuns - 1);
  const auto still = test::estimate_regions(
      test::scene_from_xml(sunlit("path", to_world(kLook), to_world(floor), to_world(ball))), regions, 64, kRuns, 10);
  for (const auto& [name, spp] : {std::pair{"path", 32}, std::pair{"ptracer", 64}, std::pair{"bdpt", 16}}) {
    const LoadedScene moving = test::scene_from_xml(
        sunlit(name, keyed({kLook, kLook + shift}), keyed({floor, floor + shift}), keyed({ball, ball + shift})));
    ASSERT_TRUE(moving->features().moving_camera);
    expect_agree(test::estimate_regions(moving, regions, spp, kRuns, 20), still, t_critical, name);
  }
}

// The camera turns 24 degrees about the vertical through where it stands,
// over the still scene: path's image is the mean of 16 still cameras at
// the midpoints of 16 equal parts of the turn, and ptracer's and bdpt's
// agree with path's.
TEST(MovingCamera, APanIsTheMeanOfStillCamerasAlongIt) {
  const auto turned = [](double angle) {
    return kLook + "<translate y='1.5' z='-1.5'/><rotate z='1' angle='" + std::to_string(angle) +
           "'/><translate y='-1.5' z='1.5'/>";
  };
  const std::string floor = to_world("<scale value='3'/>"), ball = to_world("<translate x='0.2' z='0.3'/>");
  const auto regions = test::grid_regions(24, 24, 4);
  const double t_critical = test::two_sided_t_critical(test::sidak_alpha(0.001, 3 * int(regions.size())), kRuns - 1);
  constexpr int kStill = 16;
  std::vector<test::RegionEstimate> mean(regions.size());
  for (int k = 0; k < kStill; ++k) {
    const auto one = test::estimate_regions(
        test::scene_from_xml(sunlit("path", to_world(turned(24.0 * (k + 0.5) / kStill)), floor, ball)), regions, 16,
        kRuns, 100 + 10 * k);
    for (size_t r = 0; r < regions.size(); ++r) {
      mean[r].mean += one[r].mean / kStill;
      mean[r].standard_error += one[r].standard_error * one[r].standard_error / (kStill * kStill);
    }
  }
  for (auto& m : mean) m.standard_error = std::sqrt(m.standard_error);
  const auto pan = keyed({turned(0), turned(8), turned(16), turned(24)});
  const auto path =
      test::estimate_regions(test::scene_from_xml(sunlit("path", pan, floor, ball)), regions, 64, kRuns, 30);
  expect_agree(path, mean, t_critical, "path");
  for (const auto& [name, spp] : {std::pair{"ptracer", 128}, std::pair{"bdpt", 32}})
    expect_agree(test::estimate_regions(test::scene_from_xml(sunlit(name, pan, floor, ball)), regions, spp, kRuns, 40),
                 path, t_critical, name);
}

std::string load_error(const std::string& camera) {
  return test::thrown_message<std::exception>(
      [&] { test::scene_from_xml(sunlit("path", camera, to_world("<scale value='3'/>"), ""), "moving-camera.xml"); });
}

TEST(MovingCamera, BadKeysAreRefusedByName) {
  EXPECT_THAT(load_error(keyed({kLook, kLook + "<scale value='2'/>"})),
              HasSubstr("moving-camera.xml:1: a moving camera's keys must share one scale and shear (key 2's differs "
                        "from the first's)"));
  EXPECT_THAT(load_error(to_world(kLook) + keyed({kLook, kLook})),
              HasSubstr("a sensor takes to_world as a transform or as an animation, not both"));
  EXPECT_THAT(load_error("<animation name='to_world'><transform time='0'>" + kLook +
                         "</transform><transform time='2'>" + kLook + "</transform></animation>"),
              HasSubstr("the animation's keys run from 0 to 2, and must span the sensor's shutter, from 0 to 1"));
  EXPECT_THAT(describe(test::scene_from_xml(sunlit("path", keyed({kLook, kLook}), "", ""))->features()),
              HasSubstr("motion: moving during the shutter: the camera;"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
