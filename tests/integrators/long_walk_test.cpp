// Walks that roulette cannot end: in a ball of medium with albedo 1 and
// sigma_t 1e10 a path keeps its throughput while it scatters about
// (optical depth)^2 = 1e20 times (and, its free flights far below float's
// spacing, it hardly moves). With max_depth -1 the walk stops at
// kLongestWalk segments, so the render ends; what the cut paths would have
// carried is lost.

#include <gtest/gtest.h>

#include <string>

#include "core/transport/walk_limits.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

LoadedScene dense_ball(const std::string& integrator, const std::string& sigma_t) {
  return test::scene_from_xml(
      "<scene version='3.0.0'><integrator type='" + integrator +
      "'/><sensor type='perspective'><float name='fov' value='20'/><transform name='to_world'><lookat "
      "origin='0, 0, 5' target='0, 0, 0' up='0, 1, 0'/></transform><film type='hdrfilm'><integer name='width' "
      "value='6'/><integer name='height' value='6'/><rfilter type='box'/></film></sensor>"
      "<emitter type='constant'/><medium type='homogeneous' id='dense'><float name='sigma_t' value='" +
      sigma_t +
      "'/><rgb name='albedo' value='1'/></medium><shape type='sphere'><ref name='interior' id='dense'/></shape>"
      "</scene>");
}

TEST(LongWalk, ADenseMediumOfAlbedoOneEndsItsWalks) {
  for (const char* integrator : {"path", "ptracer", "sppm"}) {
    const FilmBuffer film = test::render_scene(dense_ball(integrator, "1e10"), 4, 3);
    EXPECT_EQ(film.dropped_samples(), 0u) << integrator;
  }
}

// -1 is the longest walk: the same image, bit for bit, as max_depth 4096.
TEST(LongWalk, NoLimitIsTheLongestWalk) {
  const auto render = [](const char* max_depth) {
    return test::render_scene(
               test::scene_from_xml(
                   "<scene version='3.0.0'><integrator type='path'><integer name='max_depth' value='" +
                   std::string(max_depth) +
                   "'/></integrator><sensor type='perspective'><float name='fov' value='20'/><transform "
                   "name='to_world'><lookat origin='0, 0, 5' target='0, 0, 0' up='0, 1, 0'/></transform><film "
                   "type='hdrfilm'><integer name='width' value='6'/><integer name='height' value='6'/></film></sensor>"
                   "<emitter type='constant'/><medium type='homogeneous' id='dense'><float name='sigma_t' "
                   "value='1e3'/><rgb name='albedo' value='1'/></medium><shape type='sphere'><ref name='interior' "
                   "id='dense'/></shape></scene>"),
               4, 3)
        .resolve();
  };
  EXPECT_EQ(render("-1"), render("4096"));
  EXPECT_NE(render("-1"), render("64"));
}

TEST(LongWalk, UnlimitedWalksStopAtTheLongestWalk) {
  PathSettings unlimited;
  unlimited.max_depth = -1;
  EXPECT_EQ(camera_walk_limits(unlimited).max_segments, 4096);
  EXPECT_EQ(light_walk_limits(unlimited).max_segments, 4095);
  PathSettings five;
  five.max_depth = 5;
  EXPECT_EQ(camera_walk_limits(five).max_segments, 5);
  EXPECT_EQ(light_walk_limits(five).max_segments, 4);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
