// Moving shapes: a render of a moving scene is the time average of the
// still scenes along the motion, which the test renders itself; bad
// animations and integrators that cannot follow a time are refused by name.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <string>

#include "core/job/render_job.h"
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

// An instance moved by the keys that move the sphere directly: the same
// image, region by region within 4 standard errors (the two renders share
// their seeds, so they differ far less than that; 36 regions).
TEST(MotionBlur, AMovingInstanceMovesItsGroup) {
  const std::string keys = key(2, -0.6, 0) + key(2.5, 0, 30) + key(3, 0.6, 60);
  const LoadedScene instance = test::scene_from_xml(scene_xml(
      "<shape type='shapegroup' id='ball'><shape type='sphere'><float name='radius' value='0.3'/></shape></shape>"
      "<shape type='instance'><ref id='ball'/><animation name='to_world'>" +
          keys + "</animation></shape>",
      kShutter));
  ASSERT_TRUE(instance->features().motion);
  const LoadedScene sphere = test::scene_from_xml(scene_xml(moving_sphere(keys), kShutter));
  const auto regions = test::grid_regions(24, 24, 6);
  const auto a = test::estimate_regions(instance, regions, 16, 4, 500);
  const auto b = test::estimate_regions(sphere, regions, 16, 4, 500);
  for (size_t r = 0; r < regions.size(); ++r)
    EXPECT_LT(std::abs(test::difference_score(a[r], b[r])), 4)
        << "region " << r << ": instance " << a[r].mean << ", sphere " << b[r].mean;
}

// A white disk of radius 0.3 seen from straight above by an orthographic
// camera (the view spans +-1; image right is +x, image down is -y), its
// centre moving along y = 0.1 through x = -0.5, -0.3 and 0.4 at the
// shutter's opening, middle and closing: slow, then fast. A point is
// covered while the centre is within h = sqrt(r^2 - dy^2) of it along x,
// so the time it is covered is, per half of the shutter, the overlap of
// [x - h, x + h] with that half's sweep over the sweep's length. The albedo
// layer's samples are 0 or 1 with that probability averaged over the
// pixel (8x8 points here); regions of 4x4 pixels, 256 samples per pixel,
// each within the normal bound at 0.1 %, Sidak-corrected over 64 regions.
double time_covered(double x, double y) {
  constexpr double kRadius = 0.3, kKeys[] = {-0.5, -0.3, 0.4};
  const double dy = y - 0.1;
  if (std::abs(dy) >= kRadius) return 0;
  const double h = std::sqrt(kRadius * kRadius - dy * dy);
  double covered = 0;
  for (int k = 0; k < 2; ++k) {
    const double a = kKeys[k], b = kKeys[k + 1];
    const double overlap = std::max(0.0, std::min(b, x + h) - std::max(a, x - h));
    covered += 0.5 * overlap / (b - a);
  }
  return covered;
}

TEST(MotionBlur, AMovingDiskIsTheAnalyticSweptDisk) {
  constexpr int kPixels = 32, kSpp = 256, kBlock = 4;
  const auto disk_key = [](double time, double x) {
    return "<transform time='" + std::to_string(time) + "'><scale value='0.3'/><translate x='" + std::to_string(x) +
           "' y='0.1'/></transform>";
  };
  const LoadedScene scene = test::scene_from_xml(
      "<scene version='3.0.0'><integrator type='aov'><string name='aovs' value='a:albedo'/></integrator>"
      "<sensor type='orthographic'><float name='shutter_close' value='1'/><transform name='to_world'>"
      "<lookat origin='0, 0, 2' target='0, 0, 0' up='0, 1, 0'/></transform><film type='hdrfilm'>"
      "<integer name='width' value='32'/><integer name='height' value='32'/><rfilter type='box'/></film></sensor>"
      "<shape type='disk'><bsdf type='diffuse'><rgb name='reflectance' value='1'/></bsdf><animation "
      "name='to_world'>" +
      disk_key(0, -0.5) + disk_key(0.5, -0.3) + disk_key(1, 0.4) + "</animation></shape></scene>");
  const auto image = test::render_scene(scene, kSpp, 7).resolve();
  ASSERT_EQ(image.size(), size_t(kPixels * kPixels * 3));
  const double z = test::two_sided_z_critical(0.001 / 64);
  double total = 0;
  for (int by = 0; by < kPixels; by += kBlock)
    for (int bx = 0; bx < kPixels; bx += kBlock) {
      double expected = 0, variance = 0, measured = 0;
      for (int py = by; py < by + kBlock; ++py)
        for (int px = bx; px < bx + kBlock; ++px) {
          double p = 0;
          constexpr int n = 8;
          for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
              p += time_covered(-1 + 2 * (px + (i + 0.5) / n) / kPixels, 1 - 2 * (py + (j + 0.5) / n) / kPixels);
          p /= n * n;
          expected += p;
          variance += p * (1 - p) / kSpp;
          measured += image[size_t(py * kPixels + px) * 3 + 1];
        }
      constexpr double kCount = kBlock * kBlock;
      total += measured;
      EXPECT_LE(std::abs(measured - expected) / kCount, z * std::sqrt(variance) / kCount + 1e-6)
          << "block (" << bx << ", " << by << "): " << measured / kCount << ", expected " << expected / kCount;
    }
  // The disk's area at every time, pi r^2, over the view's 4.
  EXPECT_NEAR(total / (kPixels * kPixels), M_PI * 0.09 / 4, 0.002);
}

// A floor lit only by a ceiling, which a spot light below it lights, and a
// panel sliding between them: the same panel shades the ceiling from the
// light and the floor from the ceiling, so the light a floor point gets
// depends on both happening at one instant (subpaths or photons joined
// across two instants see the panel twice, independently, and come out
// darker). The camera looks down from below the panel, or (`above`) from
// between the panel and the ceiling, past a narrower panel: then what it
// sees of the floor depends on the panel at that instant too, as do the
// photons gathered there. `integrator` is its element; `ceiling` a
// material.
struct Panel {
  std::string ceiling;
  bool above = false;
};

LoadedScene panel_scene(const std::string& integrator, const Panel& panel) {
  const std::string height = panel.above ? "1.6" : "0.6", width = panel.above ? "0.25" : "0.5";
  return test::scene_from_xml(
      "<scene version='3.0.0'>" + integrator +
      "<sensor type='perspective'><float name='fov' value='60'/><float name='shutter_close' value='1'/>"
      "<transform name='to_world'><lookat origin='0, 0, " +
      height +
      "' target='0, 0, 0' up='0, 1, 0'/></transform>"
      "<film type='hdrfilm'><integer name='width' value='24'/><integer name='height' value='24'/>"
      "<rfilter type='box'/></film></sensor>"
      "<shape type='rectangle'><transform name='to_world'><scale value='3'/></transform></shape>"
      "<shape type='rectangle'><transform name='to_world'><scale value='3'/><rotate x='1' angle='180'/>"
      "<translate z='2'/></transform>" +
      panel.ceiling +
      "</shape><emitter type='spot'><rgb name='intensity' value='10'/><float name='cutoff_angle' value='40'/>"
      "<transform name='to_world'><lookat origin='0, 0, 0.3' target='0, 0, 1' up='0, 1, 0'/></transform>"
      "</emitter><shape type='rectangle'><animation name='to_world'><transform time='0'><scale x='" +
      width + "' y='3'/><translate x='-0.8' z='1.2'/></transform><transform time='1'><scale x='" + width +
      "' y='3'/><translate x='0.8' z='1.2'/></transform></animation></shape></scene>");
}

std::string integrator_element(const std::string& type, const std::string& extra = "") {
  return "<integrator type='" + type + "'><integer name='max_depth' value='3'/>" + extra + "</integrator>";
}

struct Contender {
  std::string integrator;
  uint32_t spp;
};

// Region means of independent runs (8 of each) of each contender against
// the oracle's, at 0.1 %, Sidak-corrected over 4 regions and the
// contenders, Student's t.
void expect_panel_agrees(const Panel& panel, const Contender& oracle, const std::vector<Contender>& others) {
  constexpr int kRuns = 8;
  const auto regions = test::grid_regions(24, 24, 2);
  const double t_critical = test::two_sided_t_critical(test::sidak_alpha(0.001, 4 * int(others.size())), kRuns - 1);
  const auto expected = test::estimate_regions(panel_scene(oracle.integrator, panel), regions, oracle.spp, kRuns, 300);
  for (const Contender& c : others) {
    const auto estimates = test::estimate_regions(panel_scene(c.integrator, panel), regions, c.spp, kRuns, 400);
    for (size_t r = 0; r < regions.size(); ++r)
      EXPECT_LT(std::abs(test::difference_score(estimates[r], expected[r])), t_critical)
          << c.integrator << " region " << r << ": " << estimates[r].mean << " +- " << estimates[r].standard_error
          << ", expected " << expected[r].mean << " +- " << expected[r].standard_error;
    EXPECT_GT(expected[0].mean, 0);
  }
}

// path, whose whole path has one time, is the oracle for a diffuse ceiling.
TEST(MotionBlur, LightAndCameraSubpathsMeetAtOneInstant) {
  expect_panel_agrees({}, {integrator_element("path"), 128},
                      {{integrator_element("bdpt"), 64},
                       {integrator_element("ptracer"), 128},
                       {integrator_element("sppm", "<integer name='photons' value='5000'/>"), 32},
                       {integrator_element("vcm"), 32}});
}

// A mirror ceiling makes the floor's light a caustic, which only light
// paths find: ptracer, each of whose paths has one time, is the oracle for
// the photons of photon, sppm and vcm (each pass sharing its time).
TEST(MotionBlur, PhotonsAndTheirGatherersMeetAtOneInstant) {
  expect_panel_agrees({"<bsdf type='conductor'/>"}, {integrator_element("ptracer"), 256},
                      {{integrator_element("photon", "<integer name='photons' value='5000'/>"), 64},
                       {integrator_element("sppm", "<integer name='photons' value='5000'/>"), 64},
                       {integrator_element("vcm"), 32},
                       {integrator_element("bdpt"), 64}});
}

// Seen from above the panel, the floor a camera path finds, and so the
// photons it gathers there, depend on the panel at the path's instant:
// sppm's, vcm's and photon's passes must give their camera paths their
// photons' time.
TEST(MotionBlur, GatherersSeeTheSceneAtTheirPhotonsInstant) {
  expect_panel_agrees(
      {"", true}, {integrator_element("path"), 128},
      {{integrator_element("sppm", "<integer name='photons' value='5000'/>"), 32}, {integrator_element("vcm"), 32}});
  expect_panel_agrees({"<bsdf type='conductor'/>", true}, {integrator_element("ptracer"), 256},
                      {{integrator_element("photon", "<integer name='photons' value='5000'/>"), 64}});
}

// A ball of fog lit from below by a spot light pointing up, over a floor
// the camera looks down at from just below the fog: the floor is lit only
// by light the fog scatters back. `fog_to_world` places the ball (a
// transform or an animation); `shapes` are added to the scene.
LoadedScene fog_scene(const std::string& integrator, const std::string& fog_to_world, const std::string& shapes) {
  return test::scene_from_xml(
      "<scene version='3.0.0'>" + integrator +
      "<sensor type='perspective'><float name='fov' value='60'/><float name='shutter_close' value='1'/>"
      "<transform name='to_world'><lookat origin='0, 0, 0.6' target='0, 0, 0' up='0, 1, 0'/></transform>"
      "<film type='hdrfilm'><integer name='width' value='24'/><integer name='height' value='24'/>"
      "<rfilter type='box'/></film></sensor>"
      "<shape type='rectangle'><transform name='to_world'><scale value='3'/></transform></shape>"
      "<emitter type='spot'><rgb name='intensity' value='10'/><float name='cutoff_angle' value='40'/>"
      "<transform name='to_world'><lookat origin='0, 0, 0.3' target='0, 0, 1' up='0, 1, 0'/></transform></emitter>"
      "<medium type='homogeneous' id='fog'><float name='sigma_t' value='3'/><rgb name='albedo' value='1'/>"
      "</medium><shape type='sphere'><float name='radius' value='0.4'/><ref name='interior' id='fog'/>" +
      fog_to_world + "</shape>" + shapes + "</scene>");
}

// Fog above a sliding panel, lit from below by a spot light through the
// panel's side, lights a floor below the panel, again past it: every path
// from the light to the floor crosses the panel's plane twice, once on each
// side of a scattering event in the fog. As the shutter opens the panel
// covers the light and the floor's view of the fog; it then slides away.
// Walks must keep the path's time past each event, in every shadow ray
// from one and in every shadow ray resumed past the fog's (null) boundary:
// one traced at time 0 finds the panel in the way. The panel at `x` (or
// moving from 0 to 1.6 when `x` is empty); `integrator`, its element.
LoadedScene fog_over_panel(const std::string& integrator, std::optional<double> f) {
  const std::string panel = "<scale x='0.5' y='3'/><translate z='1.2' x='";
  return fog_scene(integrator, "<transform name='to_world'><translate z='1.65'/></transform>",
                   "<shape type='rectangle'>" +
                       (f ? "<transform name='to_world'>" + panel + std::to_string(1.6 * *f) + "'/></transform>"
                          : "<animation name='to_world'><transform time='0'>" + panel + "0'/></transform>" +
                                "<transform time='1'>" + panel + "1.6'/></transform></animation>") +
                       "</shape>");
}

// The fog ball itself crossing the spot light's beam, slowly then fast
// (keys at x = -0.8, -0.5 and 0.8): the walk enters and leaves the fog
// where its boundary is at the path's time.
LoadedScene moving_fog(const std::string& integrator, std::optional<double> f) {
  const auto at = [](double x) { return "<translate x='" + std::to_string(x) + "' z='1.65'/>"; };
  if (f)
    return fog_scene(
        integrator,
        "<transform name='to_world'>" + at(*f < 0.5 ? -0.8 + 0.6 * *f : -0.5 + 2.6 * (*f - 0.5)) + "</transform>", "");
  return fog_scene(integrator,
                   "<animation name='to_world'><transform time='0'>" + at(-0.8) + "</transform><transform time='0.5'>" +
                       at(-0.5) + "</transform><transform time='1'>" + at(0.8) + "</transform></animation>",
                   "");
}

// Each integrator's moving render (`scene` without a fraction) against the
// mean of 16 still path renders at the midpoints of the motion (`scene` at
// those fractions of it), by 16 independent runs at 0.1 %, Sidak-corrected
// over 4 regions and 4 integrators, Student's t.
void expect_time_average_in_fog(const std::function<LoadedScene(const std::string&, std::optional<double>)>& scene) {
  constexpr int kRuns = 16, kStill = 16;
  const auto regions = test::grid_regions(24, 24, 2);
  const std::vector<std::pair<std::string, uint32_t>> integrators = {
      {integrator_element("path"), 64},
      {integrator_element("bdpt"), 128},
      {integrator_element("ptracer"), 64},
      {integrator_element("sppm", "<integer name='photons' value='5000'/>"), 32}};
  const double t_critical =
      test::two_sided_t_critical(test::sidak_alpha(0.001, int(regions.size() * integrators.size())), kRuns - 1);
  std::vector<test::RegionEstimate> average(regions.size());
  for (int k = 0; k < kStill; ++k) {
    const auto one =
        test::estimate_regions(scene(integrator_element("path"), (k + 0.5) / kStill), regions, 32, kRuns, 600 + 10 * k);
    for (size_t r = 0; r < regions.size(); ++r) {
      average[r].mean += one[r].mean / kStill;
      average[r].standard_error += one[r].standard_error * one[r].standard_error / (kStill * kStill);
    }
  }
  for (auto& a : average) a.standard_error = std::sqrt(a.standard_error);
  for (const auto& [integrator, spp] : integrators) {
    const LoadedScene moving = scene(integrator, std::nullopt);
    ASSERT_TRUE(moving->features().motion && moving->features().medium_walk);
    ASSERT_EQ(moving->features().media, 1);
    const auto estimates = test::estimate_regions(moving, regions, spp, kRuns, 800);
    for (size_t r = 0; r < regions.size(); ++r)
      EXPECT_LT(std::abs(test::difference_score(estimates[r], average[r])), t_critical)
          << integrator << " region " << r << ": " << estimates[r].mean << " +- " << estimates[r].standard_error
          << ", still scenes' mean " << average[r].mean << " +- " << average[r].standard_error;
    EXPECT_GT(estimates[0].mean, 0) << integrator;
  }
}

TEST(MotionBlur, InFogEveryIntegratorSeesTheTimeAverage) { expect_time_average_in_fog(fog_over_panel); }

TEST(MotionBlur, MovingFogIsTheTimeAverageOfStillFog) { expect_time_average_in_fog(moving_fog); }

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
  EXPECT_THAT(
      load_error(scene_xml("<shape type='sphere'><emitter type='area'/><animation name='to_world'>" + key(2, 0) +
                               "<transform time='3'><scale value='2'/></transform></animation>"
                               "</shape>",
                           kShutter)),
      HasSubstr("moving.xml:1: a moving area light's keys must share one scale and shear (key 2's differs "
                "from the first's)"));
  EXPECT_THAT(load_error(scene_xml("<medium type='heterogeneous' id='smoke'><volume name='sigma_t' type='constvolume'/>"
                                   "</medium><shape type='sphere'><ref name='interior' id='smoke'/>"
                                   "<animation name='to_world'>" +
                                       key(2, 0) + key(3, 1) + "</animation></shape>",
                                   kShutter)),
              HasSubstr("moving.xml:1: a moving shape can bound homogeneous media only: a heterogeneous medium's "
                        "density stays where its own to_world puts it"));
  const std::string moving = "<animation name='to_world'>" + key(2, 0) + key(3, 1) + "</animation>";
  EXPECT_THAT(load_error(scene_xml("<shape type='csg'><string name='operation' value='union'/><shape type='sphere'/>"
                                   "<shape type='cube'/>" +
                                       moving + "</shape>",
                                   kShutter)),
              HasSubstr("a csg cannot move yet: animate a shape of the scene's own"));
  EXPECT_THAT(load_error(scene_xml(
                  "<shape type='shapegroup' id='g'><shape type='sphere'>" + moving + "</shape></shape>", kShutter)),
              HasSubstr("a shape in a shapegroup cannot move yet"));
  EXPECT_THAT(
      load_error(scene_xml(
          "<shape type='sphere'><animation name='to_uv'>" + key(2, 0) + key(3, 1) + "</animation></shape>", kShutter)),
      HasSubstr("only to_world can be animated, not 'to_uv'"));
  EXPECT_THAT(load_error("<scene version='3.0.0'><bsdf type='diffuse'><animation name='to_world'>" + key(0, 0) +
                         key(1, 1) + "</animation></bsdf></scene>"),
              HasSubstr("only shapes, sensors and emitters can move: a moving bsdf means nothing"));
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
  settings.integrator = "radiosity";
  EXPECT_THAT(test::thrown_message<std::invalid_argument>([&] { RenderJob(moving, settings); }),
              HasSubstr("integrator 'radiosity' does not render moving shapes or cameras yet, which moving.xml has; "
                        "render it with aov, bdpt, direct, guided_path, mlt, path, photon, ptracer, sppm, vcm, "
                        "volpath"));
  EXPECT_THAT(describe(moving->features()),
              HasSubstr("motion: moving during the shutter: 1 shape; camera rays draw a time"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
