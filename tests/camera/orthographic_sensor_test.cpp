#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <random>

#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using testing::HasSubstr;

// A 40x20 film scaled by 3: local x spans [-1, 1] and y [-1/2, 1/2] before
// the scale, so the camera sees 6 x 3 scene units.
std::string ortho_xml(const std::string& transform) {
  return "<scene version='3.0.0'><sensor type='orthographic'><transform name='to_world'>" + transform +
         "</transform><film type='hdrfilm'><integer name='width' value='40'/><integer name='height' value='20'/>"
         "</film></sensor></scene>";
}

const std::string kPlacement = "<scale value='3'/><lookat origin='1, 2, 3' target='1, 2, 0' up='0, 1, 0'/>";

TEST(OrthographicSensor, ParallelRaysAcrossTheScaledFilm) {
  const auto scene = test::scene_from_xml(ortho_xml(kPlacement));
  const Sensor& cam = scene->sensor();
  EXPECT_FALSE(cam.has_lens());
  EXPECT_TRUE(cam.delta_direction());
  const Ray centre = cam.generate_ray({20, 10}, {}), corner = cam.generate_ray({0, 0}, {});
  const Ray right = cam.generate_ray({40, 10}, {});
  EXPECT_NEAR(centre.d.z, -1, 1e-6f);
  EXPECT_EQ(corner.d, centre.d);
  // Image left and top are world -x and +y seen from above; corners 3 and
  // 1.5 units from the centre.
  EXPECT_NEAR(corner.o.x - centre.o.x, -3, 1e-5f);
  EXPECT_NEAR(corner.o.y - centre.o.y, 1.5f, 1e-5f);
  EXPECT_NEAR(right.o.x - centre.o.x, 3, 1e-5f);
}

// A point seen by a camera ray connects back to the raster position it was
// seen from, along -forward, with importance 1 / (6 x 3) per unit area.
TEST(OrthographicSensor, SampleWiInvertsGenerateRay) {
  const auto scene = test::scene_from_xml(ortho_xml(kPlacement));
  const Sensor& cam = scene->sensor();
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0, 1);
  for (int i = 0; i < 100; ++i) {
    const Vec2 raster{u(rng) * 40, u(rng) * 20};
    const Ray ray = cam.generate_ray(raster, {});
    const auto wi = cam.sample_Wi({ray.at(0.5f + 2 * u(rng)), {}, {}}, {});
    ASSERT_TRUE(wi);
    EXPECT_NEAR(wi->raster.x, raster.x, 1e-3f);
    EXPECT_NEAR(wi->raster.y, raster.y, 1e-3f);
    EXPECT_NEAR(length(wi->p_lens - ray.o), 0, 1e-5f);
    EXPECT_EQ(wi->wi, -ray.d);
    EXPECT_FLOAT_EQ(wi->We.g, 1.0f / 18);
    float pdf_pos = 0, pdf_dir = 0;
    cam.pdf_We(ray, &pdf_pos, &pdf_dir);
    EXPECT_FLOAT_EQ(pdf_pos, 1.0f / 18);
  }
  EXPECT_FALSE(cam.sample_Wi({{1, 2, 4}, {}, {}}, {}));         // behind the film
  EXPECT_FALSE(cam.sample_Wi({{1 + 3.5f, 2, 0}, {}, {}}, {}));  // beside it
}

TEST(OrthographicSensor, BadPlacement) {
  EXPECT_THAT(test::load_error(ortho_xml("<scale x='0'/>")), HasSubstr("transform matrix is singular"));
  EXPECT_THAT(test::load_error(ortho_xml("<matrix value='1 0.5 0 0  0 1 0 0  0 0 1 0  0 0 0 1'/>")),
              HasSubstr("must not shear"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
