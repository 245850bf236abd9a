// Moving shapes: a render of a moving scene is the time average of the
// still scenes along the motion, which the test renders itself; bad
// animations and integrators that cannot follow a time are refused by name.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/job/render_job.h"
#include "core/scene/scene_features.h"
#include "tests/support/independent_runs.h"
#include "tests/support/test_scenes.h"
#include "tests/support/thrown_message.h"

namespace caustica {
namespace {

using testing::HasSubstr;

// A sphere over a diffuse floor under a point light, seen from above at an
// angle: it and its shadow move together. `sphere` places it.
std::string scene_xml(const std::string& sphere, const std::string& shutter = "") {
  return "<scene version='3.0.0'><integrator type='path'/><sensor type='perspective'>" + shutter +
         "<float name='fov' value='40'/><transform name='to_world'><lookat origin='0, -1.5, 3' target='0, 0, 0' "
         "up='0, 0, 1'/></transform><film type='hdrfilm'><integer name='width' value='24'/><integer name='height' "
         "value='24'/><rfilter type='box'/></film></sensor>"
         "<shape type='rectangle'><transform name='to_world'><scale value='2'/></transform></shape>"
         "<emitter type='point'><point name='position' x='0.6' y='-0.4' z='2'/><rgb name='intensity' value='4'/>"
         "</emitter>" +
         sphere + "</scene>";
}

std::string still_sphere(double x) {
  return "<shape type='sphere'><float name='radius' value='0.3'/><point name='center' x='" + std::to_string(x) +
         "' y='0' z='0.3'/></shape>";
}

// From x = -0.6 at the shutter's opening to 0.6 as it closes, with a turn
// about z on the way (a sphere looks the same turned: only its centre's
// path shows).
std::string moving_sphere(const std::string& keys) {
  return "<shape type='sphere'><float name='radius' value='0.3'/><animation name='to_world'>" + keys +
         "</animation></shape>";
}

std::string key(double time, double x, double angle = 0) {
  return "<transform time='" + std::to_string(time) + "'><rotate z='1' angle='" + std::to_string(angle) +
         "'/><translate x='" + std::to_string(x) + "' z='0.3'/></transform>";
}

const std::string kShutter = "<float name='shutter_open' value='2'/><float name='shutter_close' value='3'/>";

// The moving render's region means against the mean of 16 still renders at
// the midpoints of 16 equal parts of the motion (the midpoint rule, whose
// error over a region is far below the noise here). Every region must agree
// within 4 standard errors: with 36 regions, a false failure has a chance
// of about 0.2 %.
TEST(MotionBlur, TheImageIsTheTimeAverageOfTheStillScenes) {
  const auto regions = test::grid_regions(24, 24, 6);
  const LoadedScene moving =
      test::scene_from_xml(scene_xml(moving_sphere(key(2, -0.6, 0) + key(2.5, 0, 30) + key(3, 0.6, 60)), kShutter));
  EXPECT_TRUE(moving->features().motion);
  const auto blurred = test::estimate_regions(moving, regions, 64, 8, 1);
  constexpr int kStill = 16;
  std::vector<test::RegionEstimate> average(regions.size());
  for (int k = 0; k < kStill; ++k) {
    const double x = -0.6 + 1.2 * (k + 0.5) / kStill;
    const LoadedScene still = test::scene_from_xml(scene_xml(still_sphere(x), kShutter));
    EXPECT_FALSE(still->features().motion);
    const auto estimates = test::estimate_regions(still, regions, 16, 4, 100 + 10 * k);
    for (size_t r = 0; r < regions.size(); ++r) {
      average[r].mean += estimates[r].mean / kStill;
      average[r].standard_error += estimates[r].standard_error * estimates[r].standard_error / (kStill * kStill);
      average[r].runs = 4 * kStill;
    }
  }
  double moving_total = 0;
  for (size_t r = 0; r < regions.size(); ++r) {
    average[r].standard_error = std::sqrt(average[r].standard_error);
    EXPECT_LT(std::abs(test::difference_score(blurred[r], average[r])), 4)
        << "region " << r << ": " << blurred[r].mean << " against " << average[r].mean;
    moving_total += blurred[r].mean;
  }
  EXPECT_GT(moving_total, 0);
}

// A still scene draws no time, shutter or not: the same image bit for bit.
TEST(MotionBlur, AShutterAloneChangesNothing) {
  const auto render = [](const std::string& shutter) {
    return test::render_scene(test::scene_from_xml(scene_xml(still_sphere(0.1), shutter)), 4, 3).resolve();
  };
  EXPECT_EQ(render(""), render(kShutter));
}

std::string load_error(const std::string& xml) {
  return test::thrown_message<std::exception>([&] { test::scene_from_xml(xml, "moving.xml"); });
}

TEST(MotionBlur, BadAnimationsAreRefusedByName) {
  EXPECT_THAT(load_error(scene_xml(moving_sphere(key(2, 0) + key(3, 1) + key(2.5, 2)), kShutter)),
              HasSubstr("moving.xml:1: the animation's key times must increase (key 3 at 2.500000 follows one at "
                        "3.000000)"));
  EXPECT_THAT(load_error(scene_xml(moving_sphere(key(2, 0) + key(4, 1)), kShutter)),
              HasSubstr("the animation's keys run from 2 to 4, and must span the sensor's shutter, from 2 to 3"));
  EXPECT_THAT(load_error(scene_xml(moving_sphere(key(2, 0) + key(2.2, 1) + key(3, 2)), kShutter)),
              HasSubstr("key times must be evenly spaced (key 2 is at 2.2, not 2.5)"));
  EXPECT_THAT(load_error(scene_xml(moving_sphere(key(0, 0) + key(1, 1)))),
              HasSubstr("the sensor's shutter is closed (shutter_open 0, shutter_close 0)"));
  EXPECT_THAT(load_error(scene_xml(moving_sphere(key(2, 0)), kShutter)),
              HasSubstr("an animation needs at least two <transform time=...> keys"));
  EXPECT_THAT(
      load_error(scene_xml(moving_sphere(key(2, 0) + "<transform time='3'><scale x='0'/></transform>"), kShutter)),
      HasSubstr("moving.xml:1: transform matrix is singular"));
  EXPECT_THAT(load_error(scene_xml("<shape type='sphere'><transform name='to_world'/><animation name='to_world'>" +
                                       key(2, 0) + key(3, 1) + "</animation></shape>",
                                   kShutter)),
              HasSubstr("a shape takes to_world as a transform or as an animation, not both"));
  EXPECT_THAT(load_error(scene_xml("<shape type='sphere'><emitter type='area'/><animation name='to_world'>" +
                                       key(2, 0) + key(3, 1) + "</animation></shape>",
                                   kShutter)),
              HasSubstr("a moving shape cannot emit yet"));
  EXPECT_THAT(
      load_error(scene_xml(
          "<shape type='sphere'><animation name='to_uv'>" + key(2, 0) + key(3, 1) + "</animation></shape>", kShutter)),
      HasSubstr("only to_world can be animated, not 'to_uv'"));
  EXPECT_THAT(load_error("<scene version='3.0.0'><emitter type='point'><animation name='to_world'>" + key(0, 0) +
                         key(1, 1) + "</animation></emitter></scene>"),
              HasSubstr("only shapes can move yet: a moving emitter is not rendered"));
  EXPECT_THAT(load_error(scene_xml(still_sphere(0),
                                   "<float name='shutter_open' value='3'/><float "
                                   "name='shutter_close' value='2'/>")),
              HasSubstr("shutter_close"));
}

// As Mitsuba 0.6 wrote a moving shape: toWorld keys, and a shutter given by
// its opening and how long it stays open. The upgraded file renders as the
// same scene written for Mitsuba 3, bit for bit.
TEST(MotionBlur, Mitsuba06AnimationsAreUpgraded) {
  const std::string old_file =
      "<scene version='0.6.0'><sensor type='perspective'><float name='shutterOpen' value='2'/>"
      "<float name='shutterOpenTime' value='1'/><float name='fov' value='40'/><transform name='toWorld'>"
      "<lookat origin='0, -1.5, 3' target='0, 0, 0' up='0, 0, 1'/></transform><film type='hdrfilm'>"
      "<integer name='width' value='24'/><integer name='height' value='24'/><rfilter type='box'/></film></sensor>"
      "<shape type='rectangle'><transform name='toWorld'><scale value='2'/></transform></shape>"
      "<emitter type='point'><point name='position' x='0.6' y='-0.4' z='2'/><rgb name='intensity' value='4'/>"
      "</emitter><shape type='sphere'><float name='radius' value='0.3'/><animation name='toWorld'>" +
      key(2, -0.6) + key(3, 0.6) + "</animation></shape><integrator type='path'/></scene>";
  const LoadedScene upgraded = test::scene_from_xml(old_file, "old.xml");
  ASSERT_TRUE(upgraded->features().motion);
  const LoadedScene current = test::scene_from_xml(scene_xml(moving_sphere(key(2, -0.6) + key(3, 0.6)), kShutter));
  EXPECT_EQ(test::render_scene(upgraded, 4, 5).resolve(), test::render_scene(current, 4, 5).resolve());
}

TEST(MotionBlur, IntegratorsThatCannotFollowATimeSaySo) {
  const LoadedScene moving =
      test::scene_from_xml(scene_xml(moving_sphere(key(2, -0.6) + key(3, 0.6)), kShutter), "moving.xml");
  RenderSettings settings;
  settings.integrator = "ptracer";
  EXPECT_THAT(test::thrown_message<std::invalid_argument>([&] { RenderJob(moving, settings); }),
              HasSubstr("integrator 'ptracer' does not render moving shapes yet, which moving.xml has; render it "
                        "with aov, direct, path, volpath"));
  EXPECT_THAT(describe(moving->features()), HasSubstr("motion: 1 shape moves during the shutter"));
}

}  // namespace
}  // namespace caustica
