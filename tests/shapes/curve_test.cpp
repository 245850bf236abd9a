// linearcurve and bsplinecurve: the curve file's format and each of its
// errors; hits on a straight tube worked by hand (a cone chain of constant
// radius is a cylinder capped by spheres; a B-spline of four evenly spaced
// collinear points is the straight segment between (p0 + 4 p1 + p2) / 6 and
// (p1 + 4 p2 + p3) / 6); its area; the refusals; and a tube of albedo 0.5
// under a uniform sky of radiance 1, whose every pixel must be 0.5 (a
// convex surface sees only the sky, so one bounce is all), which a ray
// re-hitting the surface it leaves would darken.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "core/job/render_job.h"
#include "core/math/constants.h"
#include "core/shapes/curve_file.h"
#include "core/shapes/mesh_format_error.h"
#include "tests/support/test_scenes.h"
#include "tests/support/thrown_message.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using testing::HasSubstr;
namespace fs = std::filesystem;

std::string format_error(const std::string& text, size_t min_points) {
  try {
    read_curves(text, min_points);
  } catch (const MeshFormatError& e) {
    return e.what();
  }
  return "";
}

TEST(CurveFile, ReadsCurvesSeparatedByBlankLines) {
  const CurveData c = read_curves("0 0 0 0.1\n1 0 0 0.2\n\n  \n2 0 0 0.1\r\n3 1 0 0.05\n4 1 1 0\n", 2);
  ASSERT_EQ(c.points.size(), 5u);
  EXPECT_EQ(c.first, (std::vector<uint32_t>{0, 2}));
  EXPECT_FLOAT_EQ(c.points[3].p.y, 1);
  EXPECT_FLOAT_EQ(c.points[1].radius, 0.2f);
  EXPECT_FLOAT_EQ(c.points[4].radius, 0);
}

TEST(CurveFile, NamesTheLineAndTheProblem) {
  EXPECT_EQ(format_error("0 0 0 1\n1 0 0\n", 2), "line 2: expected four numbers (x y z radius), read '1 0 0'");
  EXPECT_EQ(format_error("0 0 0 1 5\n", 1), "line 1: expected four numbers (x y z radius), read '0 0 0 1 5'");
  EXPECT_EQ(format_error("0 0 0 1\n0 x 0 1\n", 2), "line 2: expected four numbers (x y z radius), read '0 x 0 1'");
  EXPECT_EQ(format_error("0 0 0 1\n0 inf 0 1\n", 2), "line 2: a control point that is not finite: '0 inf 0 1'");
  EXPECT_EQ(format_error("0 0 0 1\n0 0 0 -1\n", 2), "line 2: a negative radius: '0 0 0 -1'");
  EXPECT_EQ(format_error("0 0 0 1\n1 0 0 1\n\n0 0 0 1\n\n", 2),
            "line 4: a curve of 1 control points; it needs at least 2");
  EXPECT_EQ(format_error("0 0 0 1\n1 0 0 1\n2 0 0 1\n", 4), "line 1: a curve of 3 control points; it needs at least 4");
  EXPECT_EQ(format_error("\n \n", 2), "no control points");
}

std::string curve_scene(const std::string& type, const std::string& points, const std::string& inside = "") {
  const fs::path file = fs::temp_directory_path() / ("caustica_" + type + ".txt");
  std::ofstream(file) << points;
  return "<scene version='3.0.0'><shape type='" + type + "'><string name='filename' value='" + file.string() + "'/>" +
         inside + "</shape></scene>";
}

// Radius 0.1 along x from -1 to 1, hit from above at (x, *, z).
void expect_tube_hits(const Scene& scene, float half_length, float r) {
  for (float x : {-0.7f, 0.0f, 0.45f})
    for (float z : {-0.09f, -0.03f, 0.0f, 0.06f}) {
      const auto hit = scene.intersect({{x, 2, z}, {0, -1, 0}, kInfinity});
      ASSERT_TRUE(hit) << x << ", " << z;
      const float y = std::sqrt(r * r - z * z);
      EXPECT_NEAR(hit->t, 2 - y, 2e-5f) << x << ", " << z;
      EXPECT_NEAR(hit->ng.y, y / r, 1e-3f);
      EXPECT_NEAR(hit->ng.z, z / r, 1e-3f);
      EXPECT_NEAR(hit->ng.x, 0, 1e-3f);
      // A ray leaving the tube does not find it again.
      EXPECT_FALSE(scene.intersect(hit->spawn(normalize(Vec3{0.3f, 1, z}))));
    }
  EXPECT_FALSE(scene.intersect({{0, 2, 0.11f}, {0, -1, 0}, kInfinity}));
  EXPECT_FALSE(scene.intersect({{half_length + r + 0.01f, 2, 0}, {0, -1, 0}, kInfinity}));
}

TEST(CurveShape, LinearCurveIsACylinderCappedBySpheres) {
  const auto loaded = test::scene_from_xml(curve_scene("linearcurve", "-1 0 0 0.1\n0 0 0 0.1\n1 0 0 0.1\n"));
  expect_tube_hits(*loaded.scene, 1, 0.1f);
  // The end's cap: a sphere of radius 0.1 about (1, 0, 0), met by a ray
  // nearly along the axis (one exactly parallel to it misses the cap in
  // Embree's intersector: a ray of measure zero).
  const Vec3 o{3, 0.02f, 0}, d = normalize(Vec3{-1, 0.01f, 0});
  const Vec3 oc = o - Vec3{1, 0, 0};
  const double b = dot(oc, d), c = dot(oc, oc) - 0.01;
  const double t_cap = -b - std::sqrt(b * b - c);
  const auto cap = loaded.scene->intersect({o, d, kInfinity});
  ASSERT_TRUE(cap);
  EXPECT_NEAR(cap->t, t_cap, 2e-5);
  const Vec3 n = (o + d * float(t_cap) - Vec3{1, 0, 0}) / 0.1f;
  EXPECT_NEAR(dot(cap->ng, n), 1, 1e-4f);
  EXPECT_NEAR(loaded.scene->shapes().front()->area(), 2 * kPi * 0.1 * 2, 1e-4);
}

TEST(CurveShape, StraightBsplineIsACylinder) {
  // to_world halves the points' spacing, not the radius.
  const auto loaded = test::scene_from_xml(curve_scene("bsplinecurve", "-6 0 0 0.1\n-2 0 0 0.1\n2 0 0 0.1\n6 0 0 0.1\n",
                                                       "<transform name='to_world'><scale value='0.5'/></transform>"));
  expect_tube_hits(*loaded.scene, 1, 0.1f);
  const auto hit = loaded.scene->intersect({{0.5f, 2, 0}, {0, -1, 0}, kInfinity});
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->uv.y, 0.75f, 1e-3f);
  EXPECT_NEAR(loaded.scene->shapes().front()->area(), 2 * kPi * 0.1 * 2, 1e-4);
}

// A hair 1 mm thick, 100 m from the origin: every ray leaving it outward
// (random directions about the normal) finds nothing, and each hit lies
// on the tube to within a hundredth of its radius (float spacing there
// is 8e-6).
TEST(CurveShape, ThinHairFarFromTheOriginLeavesItselfCleanly) {
  const auto loaded = test::scene_from_xml(curve_scene(
      "bsplinecurve", "-3 0 0 0.001\n-1 0 0 0.001\n1 0 0 0.001\n3 0 0 0.001\n",
      "<transform name='to_world'><rotate z='1' angle='30'/><translate x='100' y='40' z='-20'/></transform>"));
  const Vec3 axis{std::cos(kPi / 6), std::sin(kPi / 6), 0}, centre{100, 40, -20};
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> along(-0.9f, 0.9f), across(-0.00095f, 0.00095f), unit(-1, 1);
  int hits = 0;
  for (int k = 0; k < 2000; ++k) {
    const Vec3 target = centre + axis * along(rng) + Vec3{0, 0, 1} * across(rng);
    const Vec3 from = target + Vec3{-axis.y, axis.x, 0} * 0.5f;
    const auto hit = loaded.scene->intersect({from, normalize(target - from), kInfinity});
    if (!hit) continue;
    ++hits;
    const Vec3 rel = hit->p - centre;
    const Vec3 radial = rel - axis * dot(rel, axis);
    EXPECT_NEAR(length(radial), 0.001f, 1e-5f) << k;
    Vec3 d{unit(rng), unit(rng), unit(rng)};
    if (dot(d, hit->ng) < 0) d = -d;
    if (!(dot(d, d) > 1e-4f)) continue;
    EXPECT_FALSE(loaded.scene->intersect(hit->spawn(normalize(d)))) << k;
  }
  EXPECT_GT(hits, 1900);
}

TEST(CurveShape, Refusals) {
  EXPECT_THAT(test::load_error(curve_scene("linearcurve", "0 0 0 1\n1 0 0 1\n", "<bsdf type='dielectric'/>")),
              HasSubstr("a linearcurve cannot take a material that transmits light (dielectric)"));
  EXPECT_THAT(test::load_error(curve_scene("bsplinecurve", "0 0 0 1\n1 0 0 1\n2 0 0 1\n")),
              HasSubstr("a curve of 3 control points; it needs at least 4"));
  EXPECT_THAT(test::load_error(curve_scene("linearcurve", "0 0 0 0\n1 0 0 0\n")),
              HasSubstr("every curve has radius 0"));
  EXPECT_THAT(test::load_error(curve_scene("linearcurve", "0 0 0 1\n1 0 0 1\n",
                                           "<emitter type='area'><rgb name='radiance' value='1'/></emitter>")),
              HasSubstr("emitter"));
  // Radiosity meshes surfaces through their area parametrisation, which
  // for curves jumps from hair to hair.
  const std::string fence = curve_scene("linearcurve", "0 0 0 0.1\n1 0 0 0.1\n");
  const auto radiosity = test::scene_from_xml(
      "<scene version='3.0.0'><integrator type='radiosity'/>" +
      fence.substr(fence.find("<shape"), fence.find("</scene>") - fence.find("<shape")) +
      "<shape type='rectangle'><emitter type='area'><rgb name='radiance' value='1'/></emitter></shape></scene>");
  EXPECT_THAT(test::thrown_message<std::exception>([&] { test::render_scene(radiosity, 1); }),
              HasSubstr("shape 1 ('linearcurve') is a curve, which it cannot mesh"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><shape type='linearcurve'><string name='filename' "
                               "value='/no/such/curves.txt'/></shape></scene>"),
              HasSubstr("curve file '/no/such/curves.txt' not found"));
}

TEST(CurveShape, ConvexTubeUnderAUniformSkyShowsItsAlbedo) {
  const std::string xml = curve_scene("linearcurve", "-2 0 0 0.3\n2 0 0 0.3\n",
                                      "<bsdf type='diffuse'><rgb name='reflectance' value='0.5'/></bsdf>");
  const std::string scene_xml =
      xml.substr(0, xml.size() - 8) +
      "<emitter type='constant'><rgb name='radiance' value='1'/></emitter>"
      "<integrator type='path'/><sensor type='orthographic'><transform name='to_world'><lookat origin='0, 0, 5' "
      "target='0, 0, 0' up='0, 1, 0'/></transform><film type='hdrfilm'><integer name='width' value='8'/>"
      "<integer name='height' value='8'/><rfilter type='box'/></film><sampler type='independent'/></sensor>"
      "</scene>";
  const auto loaded = test::scene_from_xml(scene_xml);
  RenderSettings settings;
  settings.spp = 256;
  settings.seed = 3;
  settings.threads = 1;
  const RenderJob job(loaded, settings);
  const std::vector<float> img = job.run().film.resolve();
  // The orthographic view spans y in (-1, 1): rows 3 and 4 lie within
  // |y| < 0.25 < 0.3, wholly on the tube.
  double sum = 0, sum2 = 0;
  int n = 0;
  const size_t channels = img.size() / 64;
  for (int y = 3; y <= 4; ++y)
    for (int x = 0; x < 8; ++x) {
      const double v = img[(size_t(y) * 8 + x) * channels];
      sum += v;
      sum2 += v * v;
      ++n;
    }
  const double mean = sum / n, se = std::sqrt((sum2 / n - mean * mean) / (n - 1));
  EXPECT_NEAR(mean, 0.5, 4 * se + 1e-3) << "standard error " << se;
  EXPECT_LT(se, 0.01);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
