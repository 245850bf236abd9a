// A moving camera, one time at a time: what it does at time t is what a
// still camera placed where the keys put it at t does, and a point a light
// path joins to its lens lands where the camera ray through that raster
// position at that time goes. The keys turn the camera about the vertical
// through itself and slide it along x, so both the angle and the offset
// are linear in t and the test places the still camera itself.

#include <gtest/gtest.h>

#include <string>

#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

const std::string kLook = "<lookat origin='0, 1, 4' target='0, 0, 0' up='0, 1, 0'/>";

std::string placed(double angle, double x) {
  return kLook + "<translate y='-1' z='-4'/><rotate y='1' angle='" + std::to_string(angle) + "'/><translate x='" +
         std::to_string(x) + "' y='1' z='4'/>";
}

LoadedScene scene(const std::string& type, const std::string& placement) {
  const std::string lens = type == "thinlens" ? "<float name='aperture_radius' value='0.1'/>" : "";
  return test::scene_from_xml("<scene version='3.0.0'><sensor type='" + type + "'>" + lens +
                              "<float name='focus_distance' value='4'/><float name='shutter_open' value='1'/>"
                              "<float name='shutter_close' value='3'/>" +
                              placement +
                              "<film type='hdrfilm'><integer name='width' value='40'/><integer name='height' "
                              "value='30'/></film></sensor></scene>");
}

void expect_near(Vec3 a, Vec3 b, float tolerance, const std::string& what) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], tolerance) << what << " axis " << i;
}

TEST(MovingSensor, AtEachTimeItIsTheStillCameraThere) {
  for (const std::string type : {"perspective", "thinlens"}) {
    const auto moving = scene(
        type, "<animation name='to_world'><transform time='1'>" + placed(0, 0) + "</transform><transform time='2'>" +
                  placed(20, 0.5) + "</transform><transform time='3'>" + placed(40, 1) + "</transform></animation>");
    ASSERT_TRUE(moving->sensor().moves());
    for (const float t : {0.0f, 0.3f, 0.5f, 0.85f, 1.0f}) {
      const auto still = scene(type, "<transform name='to_world'>" + placed(40 * t, t) + "</transform>");
      for (const Vec2 raster : {Vec2(3, 4), Vec2(20, 15), Vec2(39, 29)})
        for (const Vec2 u : {Vec2(0.2f, 0.7f), Vec2(0.9f, 0.1f)}) {
          const Ray a = moving->sensor().generate_ray(raster, u, t), b = still->sensor().generate_ray(raster, u);
          const std::string what = type + " at " + std::to_string(t);
          // Each scene is stored relative to its camera's first position.
          const auto world = [](const LoadedScene& scene, Vec3 p) {
            const Vec3d w = scene->world_point(p);
            return Vec3(float(w.x), float(w.y), float(w.z));
          };
          expect_near(world(moving, a.o), world(still, b.o), 2e-5f, what + " origin");
          expect_near(a.d, b.d, 2e-5f, what + " direction");
          EXPECT_EQ(a.time, t);
          Vec2 raster_a, raster_b;
          const Color we_a = moving->sensor().We(a, &raster_a), we_b = still->sensor().We(b, &raster_b);
          EXPECT_NEAR(we_a.r, we_b.r, 1e-3f * we_b.r) << what;
          EXPECT_NEAR(raster_a.x, raster_b.x, 1e-3f) << what;
          EXPECT_NEAR(raster_a.y, raster_b.y, 1e-3f) << what;
          float pdf_pos[2], pdf_dir[2];
          moving->sensor().pdf_We(a, &pdf_pos[0], &pdf_dir[0]);
          still->sensor().pdf_We(b, &pdf_pos[1], &pdf_dir[1]);
          EXPECT_NEAR(pdf_pos[0], pdf_pos[1], 1e-4f * pdf_pos[1]) << what;
          EXPECT_NEAR(pdf_dir[0], pdf_dir[1], 1e-3f * pdf_dir[1]) << what;
          // The camera ray's point at depth 2, joined back to the lens.
          const Vec3 p = a.at(2);
          const auto ws = moving->sensor().sample_Wi({p, {}, {}, t}, u);
          ASSERT_TRUE(ws) << what;
          const auto expected = still->sensor().sample_Wi({still->render_point(moving->world_point(p)), {}, {}, 0}, u);
          ASSERT_TRUE(expected) << what;
          expect_near(world(moving, ws->p_lens), world(still, expected->p_lens), 2e-5f, what + " lens point");
          expect_near(ws->wi, expected->wi, 2e-5f, what + " wi");
          EXPECT_NEAR(ws->raster.x, expected->raster.x, 1e-3f) << what;
          EXPECT_NEAR(ws->raster.y, expected->raster.y, 1e-3f) << what;
          EXPECT_NEAR(ws->pdf, expected->pdf, 1e-3f * expected->pdf) << what;
        }
    }
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
