#include "core/camera/pixel_angle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

LoadedScene camera(const std::string& sensor, int width) {
  const std::string lens = sensor == "thinlens" ? "<float name='aperture_radius' value='0.1'/>" : "";
  return test::scene_from_xml("<scene version='3.0.0'><sensor type='" + sensor + "'>" + lens +
                              "<float name='fov' value='90'/><film type='hdrfilm'><integer name='width' value='" +
                              std::to_string(width) + "'/><integer name='height' value='64'/></film></sensor></scene>");
}

// The two centre pixels' rays, at screen coordinates +-tan(45 deg) / width
// of a 90-degree view, are 2 atan(1 / width) apart.
TEST(PixelAngle, PerspectiveCentrePixel) {
  for (int width : {64, 512}) {
    const double expected = 2 * std::atan(1.0 / width) * 180 / std::numbers::pi;
    EXPECT_NEAR(degrees_per_pixel(camera("perspective", width)->sensor()), expected, 1e-4 * expected) << width;
    EXPECT_NEAR(degrees_per_pixel(camera("thinlens", width)->sensor()), expected, 1e-4 * expected) << width;
  }
}

TEST(PixelAngle, OrthographicRaysAreParallel) {
  const auto scene = test::scene_from_xml("<scene version='3.0.0'><sensor type='orthographic'/></scene>");
  EXPECT_EQ(degrees_per_pixel(scene->sensor()), 0);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
