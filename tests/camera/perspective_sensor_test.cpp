#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <random>

#include "core/math/constants.h"
#include "core/sampling/warp.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

LoadedScene camera_scene(const std::string& axis, int w, int h) {
  return test::scene_from_xml(
      "<scene version='3.0.0'><sensor type='perspective'><float name='fov' value='50'/>"
      "<string name='fov_axis' value='" +
      axis +
      "'/><transform name='to_world'><lookat origin='1, 2, 3' target='0, 0, 0' up='0, 1, 0'/></transform>"
      "<film type='hdrfilm'><integer name='width' value='" +
      std::to_string(w) + "'/><integer name='height' value='" + std::to_string(h) + "'/></film></sensor></scene>");
}

float angle_deg(Vec3 a, Vec3 b) { return std::acos(std::clamp(dot(a, b), -1.0f, 1.0f)) * 180 / kPi; }

TEST(PerspectiveSensor, FovAppliesToTheChosenAxis) {
  const auto x = camera_scene("x", 200, 100);
  const Sensor& cx = x->sensor();
  EXPECT_NEAR(angle_deg(cx.generate_ray({0, 50}, {}).d, cx.generate_ray({200, 50}, {}).d), 50, 1e-3);
  const auto smaller = camera_scene("smaller", 200, 100);  // the height is smaller
  const Sensor& cs = smaller->sensor();
  EXPECT_NEAR(angle_deg(cs.generate_ray({100, 0}, {}).d, cs.generate_ray({100, 100}, {}).d), 50, 1e-3);
}

// As Mitsuba: a 35 mm-equivalent focal length sets the field of view across
// the diagonal of 36 x 24 mm film; on a 3:2 film 50mm spans 2 atan(36 / 100)
// horizontally.
TEST(PerspectiveSensor, FocalLengthSetsTheDiagonalFov) {
  const auto scene = test::scene_from_xml(
      "<scene version='3.0.0'><sensor type='perspective'><string name='focal_length' value='50mm'/>"
      "<film type='hdrfilm'><integer name='width' value='300'/><integer name='height' value='200'/></film>"
      "</sensor></scene>");
  const Sensor& cam = scene->sensor();
  EXPECT_NEAR(angle_deg(cam.generate_ray({0, 100}, {}).d, cam.generate_ray({300, 100}, {}).d),
              2 * std::atan(0.36) * 180 / M_PI, 1e-3);
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><sensor type='perspective'><string name='focal_length' "
                               "value='fifty'/></sensor></scene>"),
              testing::HasSubstr("must be a positive length in millimetres"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><sensor type='perspective'><float name='fov' value='30'/>"
                               "<string name='focal_length' value='50mm'/></sensor></scene>"),
              testing::HasSubstr("give either fov or focal_length, not both"));
}

// A view so narrow that its window on the image plane has no area as a
// float (importance is one over it) is refused, by fov or focal length.
TEST(PerspectiveSensor, AViewTooNarrowForFloatIsRefused) {
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><sensor type='perspective'><float name='fov' value='1e-30'/>"
                               "</sensor></scene>"),
              testing::HasSubstr("test.xml:1: parameter 'fov' of sensor 'perspective': gives a view too narrow for "
                                 "single precision (its window on the image plane has no area as a float)"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><sensor type='perspective'><string name='focal_length' "
                               "value='1e30mm'/></sensor></scene>"),
              testing::HasSubstr("parameter 'focal_length' of sensor 'perspective': gives a view too narrow"));
  EXPECT_NO_THROW(test::scene_from_xml(
      "<scene version='3.0.0'><sensor type='perspective'><float name='fov' value='1e-10'/></sensor></scene>"));
}

// Without fov or focal_length, Mitsuba's 50 mm lens: on the default 4:3
// film (768x576) the diagonal's tangent 0.432666 becomes 0.346133 across x.
TEST(PerspectiveSensor, DefaultIsAFiftyMillimetreLens) {
  const auto scene = test::scene_from_xml("<scene version='3.0.0'><sensor type='perspective'/></scene>");
  const Sensor& cam = scene->sensor();
  EXPECT_NEAR(angle_deg(cam.generate_ray({0, 288}, {}).d, cam.generate_ray({768, 288}, {}).d),
              2 * std::atan(std::sqrt(36.0 * 36 + 24 * 24) / 100 * 768 / 960) * 180 / M_PI, 1e-3);
}

TEST(PerspectiveSensor, CentreLooksAtTargetAndImageXGoesRight) {
  const auto scene = camera_scene("x", 64, 48);
  const Sensor& cam = scene->sensor();
  const Ray centre = cam.generate_ray({32, 24}, {});
  const Vec3 forward = normalize(Vec3(-1, -2, -3));
  EXPECT_NEAR(dot(centre.d, forward), 1, 1e-6f);
  // Looking from +z-ish toward the origin with y up, image right is world +x-ish.
  const Vec3 right = normalize(cross(forward, Vec3(0, 1, 0)));
  EXPECT_GT(dot(cam.generate_ray({64, 24}, {}).d, right), 0);
  EXPECT_GT(cam.generate_ray({32, 0}, {}).d.y, centre.d.y);  // raster y grows downward
}

// Connecting a point to the lens lands where the camera ray through that
// point started, and the importance is consistent with pdf_We.
TEST(PerspectiveSensor, SampleWiInvertsGenerateRay) {
  const auto scene = camera_scene("x", 64, 48);
  const Sensor& cam = scene->sensor();
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0, 1);
  for (int i = 0; i < 100; ++i) {
    const Vec2 raster{u(rng) * 64, u(rng) * 48};
    const Ray ray = cam.generate_ray(raster, {});
    const Vec3 p = ray.at(1 + 5 * u(rng));
    const auto wi = cam.sample_Wi({p, {}, {}}, {});
    ASSERT_TRUE(wi);
    EXPECT_NEAR(wi->raster.x, raster.x, 1e-2f);
    EXPECT_NEAR(wi->raster.y, raster.y, 1e-2f);
    float pdf_pos = 0, pdf_dir = 0;
    cam.pdf_We({wi->p_lens, -wi->wi}, &pdf_pos, &pdf_dir);
    const float cos_theta = dot(-wi->wi, normalize(Vec3(-1, -2, -3)));
    EXPECT_NEAR(wi->We.r * cos_theta, pdf_dir, 1e-4f * pdf_dir);
  }
}

TEST(PerspectiveSensor, ClippedPointsCannotConnectToTheLens) {
  const auto scene = test::scene_from_xml(
      "<scene version='3.0.0'><sensor type='perspective'><float name='near_clip' value='1'/>"
      "<float name='far_clip' value='10'/></sensor></scene>");
  const Sensor& cam = scene->sensor();
  EXPECT_FALSE(cam.sample_Wi({{0, 0, 0.5f}, {}, {}}, {}));
  EXPECT_TRUE(cam.sample_Wi({{0, 0, 5}, {}, {}}, {}));
  EXPECT_FALSE(cam.sample_Wi({{0, 0, 11}, {}, {}}, {}));
  EXPECT_FALSE(scene->intersect(cam.generate_ray({384, 288}, {})));  // nothing to hit, near plane respected
}

// We is normalised: integrated against cos theta over the directions that
// reach the film it gives 1, which is what lets light paths splat onto it.
TEST(PerspectiveSensor, ImportanceIntegratesToOne) {
  const auto scene = camera_scene("diagonal", 40, 30);
  const Sensor& cam = scene->sensor();
  const Ray centre = cam.generate_ray({20, 15}, {});
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0, kOneMinusEpsilon);
  double sum = 0;
  const int n = 400000;
  for (int i = 0; i < n; ++i) {
    const Vec3 d = square_to_uniform_sphere({u(rng), u(rng)});
    Vec2 raster;
    sum += cam.We({centre.o, d}, &raster).r * std::max(0.0f, dot(d, centre.d)) / uniform_sphere_pdf();
  }
  EXPECT_NEAR(sum / n, 1.0, 0.03);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
