// Lights that move over the shutter (point, spot, area, directional and
// environment), seen by camera paths (path: next-event estimation at the
// path's time) and by light paths (ptracer, bdpt) and photon passes (sppm,
// vcm), which must emit from where the light is at their time. The oracle
// is the mean of still renders at the midpoints of 16 (or more) equal parts
// of the motion (the midpoint rule's error is far below the noise here);
// every integrator's region means are compared with it by independent runs
// at 0.1 %, Sidak-corrected over the regions and integrators, Student's t.
// Seeds are fixed.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "core/scene/scene_features.h"
#include "tests/support/chi2.h"
#include "tests/support/env_map_file.h"
#include "tests/support/independent_runs.h"
#include "tests/support/test_scenes.h"
#include "tests/support/thrown_message.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using testing::HasSubstr;

constexpr int kRuns = 8;

// A ball on a floor, seen from above at an angle, lit by `light` alone.
std::string scene_xml(const std::string& integrator, const std::string& light) {
  return "<scene version='3.0.0'>" + integrator +
         "<sensor type='perspective'><float name='fov' value='45'/><float name='shutter_close' value='1'/>"
         "<transform name='to_world'><lookat origin='0, -1.5, 2.5' target='0, 0, 0' up='0, 0, 1'/></transform>"
         "<film type='hdrfilm'><integer name='width' value='24'/><integer name='height' value='24'/>"
         "<rfilter type='box'/></film></sensor>"
         "<shape type='rectangle'><transform name='to_world'><scale value='2'/></transform></shape>"
         "<shape type='sphere'><float name='radius' value='0.3'/><point name='center' x='0' y='0' z='0.3'/></shape>" +
         light + "</scene>";
}

std::string integrator(const std::string& type, const std::string& extra = "") {
  return "<integrator type='" + type + "'><integer name='max_depth' value='3'/>" + extra + "</integrator>";
}

std::string keyed(const std::string& emitter, const std::vector<std::string>& keys) {
  std::string out = "<emitter " + emitter + "<animation name='to_world'>";
  for (size_t k = 0; k < keys.size(); ++k)
    out += "<transform time='" + std::to_string(double(k) / double(keys.size() - 1)) + "'>" + keys[k] + "</transform>";
  return out + "</animation></emitter>";
}

// The moving light against the mean of `stills` still lights placed by
// `still` (at a fraction of the motion), for each integrator.
void expect_time_average(const std::string& moving, const std::function<std::string(double)>& still,
                         const std::vector<std::pair<std::string, uint32_t>>& integrators, int stills = 16) {
  const auto regions = test::grid_regions(24, 24, 4);
  const double t_critical =
      test::two_sided_t_critical(test::sidak_alpha(0.001, int(regions.size() * integrators.size())), kRuns - 1);
  std::vector<test::RegionEstimate> mean(regions.size());
  for (int k = 0; k < stills; ++k) {
    const auto one =
        test::estimate_regions(test::scene_from_xml(scene_xml(integrator("path"), still((k + 0.5) / stills))), regions,
                               16, kRuns, 100 + 10 * k);
    for (size_t r = 0; r < regions.size(); ++r) {
      mean[r].mean += one[r].mean / stills;
      mean[r].standard_error += one[r].standard_error * one[r].standard_error / (stills * stills);
    }
  }
  for (auto& m : mean) m.standard_error = std::sqrt(m.standard_error);
  for (const auto& [element, spp] : integrators) {
    const LoadedScene scene = test::scene_from_xml(scene_xml(element, moving));
    ASSERT_EQ(scene->features().moving_lights, 1);
    const auto estimates = test::estimate_regions(scene, regions, spp, kRuns, 300);
    double total = 0;
    for (size_t r = 0; r < regions.size(); ++r) {
      EXPECT_LT(std::abs(test::difference_score(estimates[r], mean[r])), t_critical)
          << element << " region " << r << ": " << estimates[r].mean << " +- " << estimates[r].standard_error
          << ", still lights' mean " << mean[r].mean << " +- " << mean[r].standard_error;
      total += estimates[r].mean;
    }
    EXPECT_GT(total, 0) << element;
  }
}

const std::vector<std::pair<std::string, uint32_t>> kIntegrators = {
    {integrator("path"), 32},
    {integrator("ptracer"), 64},
    {integrator("bdpt"), 16},
    {integrator("sppm", "<integer name='photons' value='5000'/>"), 32},
    {integrator("vcm"), 16}};

// A point light crossing above the ball, slowly then fast (keys at -0.8,
// -0.4 and 0.8 along x): its shadow sweeps the floor.
TEST(MovingLight, APointLightIsTheMeanOfStillOnesAlongItsPath) {
  const auto x_at = [](double f) { return f < 0.5 ? -0.8 + 0.8 * f : -0.4 + 2.4 * (f - 0.5); };
  const auto place = [](double x) { return "<translate x='" + std::to_string(x) + "' y='-0.3' z='1.5'/>"; };
  const std::string emitter = "type='point'><rgb name='intensity' value='3'/>";
  expect_time_average(
      keyed(emitter, {place(-0.8), place(-0.4), place(0.8)}),
      [&](double f) {
        return "<emitter " + emitter + "<transform name='to_world'>" + place(x_at(f)) + "</transform></emitter>";
      },
      kIntegrators);
}

// A spot light above the ball turning 40 degrees about the x axis through
// itself: its cone sweeps across the floor.
TEST(MovingLight, ASpotLightTurningIsTheMeanOfStillOnes) {
  const auto turned = [](double angle) {
    return "<lookat origin='0, 0, 2' target='0, 0, 0' up='0, 1, 0'/><translate z='-2'/><rotate x='1' angle='" +
           std::to_string(angle) + "'/><translate z='2'/>";
  };
  const std::string emitter =
      "type='spot'><rgb name='intensity' value='6'/><float name='cutoff_angle' value='25'/>"
      "<float name='beam_width' value='20'/>";
  expect_time_average(
      keyed(emitter, {turned(-20), turned(0), turned(20)}),
      [&](double f) {
        return "<emitter " + emitter + "<transform name='to_world'>" + turned(-20 + 40 * f) + "</transform></emitter>";
      },
      kIntegrators);
}

// A small glowing ball crossing above the ball on the floor, slowly then
// fast, as the point light does: the light of a moving shape is where the
// shape is, for next-event estimation, for paths that hit it and for the
// light paths and photons it sends.
TEST(MovingLight, AnAreaLightMovesWithItsShape) {
  const auto x_at = [](double f) { return f < 0.5 ? -0.8 + 0.8 * f : -0.4 + 2.4 * (f - 0.5); };
  const auto place = [](double x) { return "<translate x='" + std::to_string(x) + "' y='-0.3' z='1.5'/>"; };
  const std::string ball =
      "<shape type='sphere'><float name='radius' value='0.1'/><emitter type='area'><rgb name='radiance' "
      "value='30'/></emitter>";
  expect_time_average(
      ball + "<animation name='to_world'><transform time='0'>" + place(-0.8) + "</transform><transform time='0.5'>" +
          place(-0.4) + "</transform><transform time='1'>" + place(0.8) + "</transform></animation></shape>",
      [&](double f) { return ball + "<transform name='to_world'>" + place(x_at(f)) + "</transform></shape>"; },
      kIntegrators);
}

// A square light facing down, scaled to 0.3 across, tilting from -30 to
// 30 degrees about its own centre: the scale stays with the shape and the
// keys turn it.
TEST(MovingLight, AScaledAreaLightTurns) {
  const auto tilted = [](double angle) {
    return "<scale value='0.15'/><rotate x='1' angle='180'/><rotate y='1' angle='" + std::to_string(angle) +
           "'/><translate z='1.2'/>";
  };
  const std::string square = "<shape type='rectangle'><emitter type='area'><rgb name='radiance' value='20'/></emitter>";
  expect_time_average(
      square + "<animation name='to_world'><transform time='0'>" + tilted(-30) + "</transform><transform time='0.5'>" +
          tilted(0) + "</transform><transform time='1'>" + tilted(30) + "</transform></animation></shape>",
      [&](double f) { return square + "<transform name='to_world'>" + tilted(-30 + 60 * f) + "</transform></shape>"; },
      kIntegrators);
}

// The sun turning 120 degrees about the x axis: the ball's shadow sweeps
// the floor. Two keys also translate the light, which moves nothing
// infinitely far; light paths enter through a disk across the scene that
// must turn about the scene's centre to keep covering it. So wide a turn
// takes 64 still suns: with 16, the midpoint rule's error in the floor's
// cosine (h^2 / 24 of it, 0.07 %) shows. sppm is left out: its direct
// light from a delta sun is next-event estimation at 32 evenly spread pass
// times, nearly free of noise (1e-5 on the lit floor), so its progressive
// bias there (0.08 %) would fail it; the turning sky checks sppm.
TEST(MovingLight, ASunTurningIsTheMeanOfStillOnes) {
  const auto turned = [](double angle) { return "<rotate x='1' angle='" + std::to_string(angle) + "'/>"; };
  const std::string emitter = "type='directional'><rgb name='irradiance' value='2'/>";
  expect_time_average(
      keyed(emitter, {turned(120) + "<translate x='3'/>", turned(180), turned(240) + "<translate y='-5' z='2'/>"}),
      [&](double f) {
        return "<emitter " + emitter + "<transform name='to_world'>" + turned(120 + 120 * f) + "</transform></emitter>";
      },
      {kIntegrators[0], kIntegrators[1], kIntegrators[2], kIntegrators[4]}, 64);
}

// A sky with a bright patch turning a third of the way round the vertical:
// what rays leaving the scene meet, what next-event estimation samples and
// what light paths carry all turn with it. Then a mirror ball beside the
// diffuse one shows the sky, which only camera paths that leave the scene
// find (light paths cannot join the camera through a mirror).
TEST(MovingLight, AnEnvironmentTurningIsTheMeanOfStillOnes) {
  const auto sky = test::write_env_map(
      "caustica_moving_sky.exr",
      [](int x, int y) { return Color(0.2f) + (x >= 4 && x < 8 && y >= 4 && y < 6 ? Color(12, 10, 8) : Color()); }, 32,
      16);
  const auto turned = [](double angle) {
    return "<rotate x='1' angle='90'/><rotate z='1' angle='" + std::to_string(angle) + "'/>";
  };
  const std::string emitter = "type='envmap'><string name='filename' value='" + sky.string() + "'/>";
  const auto still = [&](double f) {
    return "<emitter " + emitter + "<transform name='to_world'>" + turned(120 * f) + "</transform></emitter>";
  };
  const std::string moving = keyed(emitter, {turned(0), turned(60), turned(120)});
  expect_time_average(moving, still, kIntegrators);
  const std::string mirror =
      "<shape type='sphere'><float name='radius' value='0.25'/><point name='center' x='0.6' y='-0.2' z='0.25'/>"
      "<bsdf type='conductor'/></shape>";
  expect_time_average(moving + mirror, [&](double f) { return still(f) + mirror; },
                      {{integrator("path"), 128}, {integrator("bdpt"), 128}, {integrator("vcm"), 128}});
}

std::string load_error(const std::string& light) {
  return test::thrown_message<std::exception>(
      [&] { test::scene_from_xml(scene_xml(integrator("path"), light), "moving-light.xml"); });
}

TEST(MovingLight, WhatCannotMoveIsRefusedByName) {
  const std::string a = "<translate x='-1'/>", b = "<translate x='1'/>";
  EXPECT_THAT(load_error(keyed("type='directional'>", {a, b + "<scale x='2'/>"})),
              HasSubstr("moving-light.xml:1: a moving light's keys must share one scale and shear (key 2's differs "
                        "from the first's)"));
  EXPECT_THAT(load_error(keyed("type='point'>", {a, b + "<scale value='2'/>"})),
              HasSubstr("a moving light's keys must share one scale and shear (key 2's differs from the first's)"));
  EXPECT_THAT(load_error("<emitter type='point'><animation name='to_world'><transform time='0'>" + a +
                         "</transform><transform time='3'>" + b + "</transform></animation></emitter>"),
              HasSubstr("the animation's keys run from 0 to 3, and must span the sensor's shutter, from 0 to 1"));
  EXPECT_THAT(load_error("<emitter type='point'><animation name='to_world'><transform time='0'>" + a +
                         "</transform></animation></emitter>"),
              HasSubstr("an animation needs at least two <transform time=...> keys"));
  EXPECT_THAT(describe(test::scene_from_xml(scene_xml(integrator("path"), keyed("type='point'>", {a, b})))->features()),
              HasSubstr("motion: moving during the shutter: 1 light;"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
