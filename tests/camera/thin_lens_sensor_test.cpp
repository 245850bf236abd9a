#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "core/math/constants.h"
#include "core/sampling/warp.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using testing::HasSubstr;

std::string sensor_xml(const std::string& type, const std::string& lens) {
  return "<scene version='3.0.0'><sensor type='" + type + "'><float name='fov' value='50'/>" + lens +
         "<transform name='to_world'><lookat origin='1, 2, 3' target='0, 0, 0' up='0, 1, 0'/></transform>"
         "<film type='hdrfilm'><integer name='width' value='64'/><integer name='height' value='48'/></film>"
         "</sensor></scene>";
}

const std::string kLens = "<float name='aperture_radius' value='0.3'/><float name='focus_distance' value='2.5'/>";

// Every ray of one raster position, whatever its lens point, passes through
// the point the pinhole camera sees there at depth focus_distance; rays
// start on the lens disk, in the plane through the camera facing forward.
TEST(ThinLensSensor, RaysMeetOnThePlaneInFocus) {
  const auto lens = test::scene_from_xml(sensor_xml("thinlens", kLens));
  const auto pinhole = test::scene_from_xml(sensor_xml("perspective", ""));
  const Vec3 forward = normalize(Vec3(-1, -2, -3));
  std::mt19937 rng(2);
  std::uniform_real_distribution<float> u(0, 1);
  for (int i = 0; i < 50; ++i) {
    const Vec2 raster{u(rng) * 64, u(rng) * 48};
    const Ray through_pinhole = pinhole->sensor().generate_ray(raster, {});
    const Vec3 in_focus = through_pinhole.at(2.5f / dot(through_pinhole.d, forward));
    const Ray ray = lens->sensor().generate_ray(raster, {u(rng), u(rng)});
    const Vec3 offset = ray.o - through_pinhole.o;
    EXPECT_NEAR(dot(offset, forward), 0, 1e-5f);
    EXPECT_LE(length(offset), 0.3f + 1e-5f);
    const Vec3 hit = ray.at(2.5f / dot(ray.d, forward));
    EXPECT_NEAR(length(hit - in_focus), 0, 1e-4f) << i;
  }
}

// Connecting a point to the lens: the raster position is where the camera
// ray through that lens point and the point lands, the importance agrees
// with pdf_We, and the density is per unit area of the lens.
TEST(ThinLensSensor, SampleWiInvertsGenerateRay) {
  const auto scene = test::scene_from_xml(sensor_xml("thinlens", kLens));
  const Sensor& cam = scene->sensor();
  EXPECT_TRUE(cam.has_lens());
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0, 1);
  for (int i = 0; i < 100; ++i) {
    const Vec2 raster{u(rng) * 64, u(rng) * 48}, u_lens{u(rng), u(rng)};
    const Ray ray = cam.generate_ray(raster, u_lens);
    const Vec3 p = ray.at(1 + 5 * u(rng));
    const auto wi = cam.sample_Wi({p, {}, {}}, u_lens);
    ASSERT_TRUE(wi);
    EXPECT_NEAR(length(wi->p_lens - ray.o), 0, 1e-5f);
    EXPECT_NEAR(wi->raster.x, raster.x, 1e-2f);
    EXPECT_NEAR(wi->raster.y, raster.y, 1e-2f);
    float pdf_pos = 0, pdf_dir = 0;
    cam.pdf_We({wi->p_lens, -wi->wi}, &pdf_pos, &pdf_dir);
    EXPECT_NEAR(pdf_pos, 1 / (kPi * 0.09f), 1e-4f);
    const float cos_theta = dot(-wi->wi, normalize(Vec3(-1, -2, -3)));
    EXPECT_NEAR(wi->We.r * cos_theta, pdf_pos * pdf_dir, 1e-4f * pdf_pos * pdf_dir);
    const float dist2 = squared_length(p - wi->p_lens);
    EXPECT_NEAR(wi->pdf, dist2 * pdf_pos / cos_theta, 1e-4f * wi->pdf);
  }
}

// We integrates to one over the lens's area and the directions leaving it.
TEST(ThinLensSensor, ImportanceIntegratesToOne) {
  const auto scene = test::scene_from_xml(sensor_xml("thinlens", kLens));
  const Sensor& cam = scene->sensor();
  const Vec3 forward = normalize(Vec3(-1, -2, -3));
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0, kOneMinusEpsilon);
  double sum = 0;
  const int n = 400000;
  for (int i = 0; i < n; ++i) {
    const Ray lens_ray = cam.generate_ray({32, 24}, {u(rng), u(rng)});  // a uniform point on the lens
    const Vec3 d = square_to_uniform_sphere({u(rng), u(rng)});
    Vec2 raster;
    sum += cam.We({lens_ray.o, d}, &raster).r * std::max(0.0f, dot(d, forward)) * (kPi * 0.09f) / uniform_sphere_pdf();
  }
  EXPECT_NEAR(sum / n, 1.0, 0.03);
}

// With no aperture the thin lens is the pinhole, ray for ray.
TEST(ThinLensSensor, ZeroApertureIsThePinhole) {
  const auto lens = test::scene_from_xml(
      sensor_xml("thinlens", "<float name='aperture_radius' value='0'/><float name='focus_distance' value='2'/>"));
  const auto pinhole = test::scene_from_xml(sensor_xml("perspective", ""));
  EXPECT_FALSE(lens->sensor().has_lens());
  // So is a lens whose area underflows float.
  const auto tiny = test::scene_from_xml(
      sensor_xml("thinlens", "<float name='aperture_radius' value='1e-30'/><float name='focus_distance' value='2'/>"));
  EXPECT_FALSE(tiny->sensor().has_lens());
  const Ray a = lens->sensor().generate_ray({10, 20}, {0.9f, 0.1f}), b = pinhole->sensor().generate_ray({10, 20}, {});
  EXPECT_EQ(a.o, b.o);
  EXPECT_EQ(a.d, b.d);
}

// A focus far beyond float's squares (1e20, 3.3e38) is infinity for the
// lens: its rays are the pinhole's directions from their lens points, and
// light joined to the lens lands back on their raster positions.
TEST(ThinLensSensor, AFarFocusIsInfinity) {
  const auto pinhole = test::scene_from_xml(sensor_xml("perspective", ""));
  for (const char* focus : {"1e20", "3.3e38"}) {
    const auto lens = test::scene_from_xml(
        sensor_xml("thinlens", "<float name='aperture_radius' value='0.5'/><float name='focus_distance' value='" +
                                   std::string(focus) + "'/>"));
    std::mt19937 rng(4);
    std::uniform_real_distribution<float> u(0, 1);
    for (int i = 0; i < 50; ++i) {
      const Vec2 raster{u(rng) * 64, u(rng) * 48};
      const Ray ray = lens->sensor().generate_ray(raster, {u(rng), u(rng)});
      const Vec3 d = pinhole->sensor().generate_ray(raster, {}).d;
      EXPECT_NEAR(length(ray.d - d), 0, 1e-6f) << focus;
      EXPECT_TRUE(std::isfinite(ray.t_min) && std::isfinite(ray.t_max)) << focus;
      Vec2 back;
      EXPECT_GT(lens->sensor().We(ray, &back).r, 0) << focus;
      EXPECT_NEAR(back.x, raster.x, 1e-3f) << focus;
      EXPECT_NEAR(back.y, raster.y, 1e-3f) << focus;
    }
  }
}

TEST(ThinLensSensor, BadParameters) {
  EXPECT_THAT(test::load_error(sensor_xml("thinlens", "")), HasSubstr("aperture_radius"));
  EXPECT_THAT(test::load_error(sensor_xml("thinlens", "<float name='aperture_radius' value='-1'/>")),
              HasSubstr("parameter 'aperture_radius' of sensor 'thinlens': must be zero or more"));
  EXPECT_THAT(test::load_error(sensor_xml("thinlens",
                                          "<float name='aperture_radius' value='1'/>"
                                          "<float name='focus_distance' value='0'/>")),
              HasSubstr("parameter 'focus_distance' of sensor 'thinlens': must be positive"));
  EXPECT_THAT(test::load_error(sensor_xml("thinlens", "<float name='aperture_radius' value='2e8'/>")),
              HasSubstr("parameter 'aperture_radius' of sensor 'thinlens': must be at most 1e8: rays from the "
                        "lens's edge start beyond what caustica traces in single precision"));
  EXPECT_NO_THROW(test::scene_from_xml(sensor_xml("thinlens", "<float name='aperture_radius' value='1e8'/>")));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
