#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

TEST(AovIntegrator, AlbedoNormalDepthAtTheFirstHit) {
  const auto scene = test::scene_from_xml(
      "<scene version='3.0.0'><integrator type='aov'><string name='aovs' value='a:albedo,n:sh_normal,d:depth,"
      "p:position'/></integrator><sensor type='perspective'><float name='near_clip' value='0.5'/>"
      "<transform name='to_world'><lookat origin='0, 0, 3' target='0, 0, 0'/></transform>"
      "<film type='hdrfilm'><integer name='width' value='3'/><integer name='height' value='3'/>"
      "<rfilter type='box'/></film></sensor><shape type='rectangle'><bsdf type='diffuse'>"
      "<rgb name='reflectance' value='0.1, 0.2, 0.3'/></bsdf></shape></scene>");
  const auto channels = scene.integrator->channels();
  ASSERT_EQ(channels.size(), 10u);
  EXPECT_EQ(channels[0], "a.R");
  EXPECT_EQ(channels[5], "n.Z");
  EXPECT_EQ(channels[6], "d.T");
  const auto img = test::render_scene(scene, 1).resolve();
  const float* centre = &img[4 * 10];
  EXPECT_FLOAT_EQ(centre[0], 0.1f);
  EXPECT_FLOAT_EQ(centre[2], 0.3f);
  EXPECT_FLOAT_EQ(centre[5], 1);  // the rectangle faces +z, toward the camera
  // Depth is measured from the camera, not from the near clipping plane.
  const float* p = &centre[7];
  EXPECT_NEAR(centre[6], std::sqrt(p[0] * p[0] + p[1] * p[1] + 9), 1e-5f);
  EXPECT_NEAR(centre[6], 3, 0.2f);
}

TEST(AovIntegrator, MediaAndTheirNullBoundariesAreLookedThrough) {
  // The same rectangle behind a fog ball (a null sphere): the same values,
  // depth included.
  const auto scene_with = [](const std::string& extra) {
    return test::scene_from_xml(
        "<scene version='3.0.0'><integrator type='aov'><string name='aovs' value='a:albedo,d:depth'/></integrator>"
        "<medium type='homogeneous' id='fog'><float name='sigma_t' value='5'/></medium>"
        "<sensor type='perspective'><transform name='to_world'><lookat origin='0, 0, 3' target='0, 0, 0'/>"
        "</transform><film type='hdrfilm'><integer name='width' value='3'/><integer name='height' value='3'/>"
        "<rfilter type='box'/></film></sensor><shape type='rectangle'><bsdf type='diffuse'>"
        "<rgb name='reflectance' value='0.1, 0.2, 0.3'/></bsdf></shape>" +
        extra + "</scene>");
  };
  const auto fogged = scene_with(
      "<shape type='sphere'><point name='center' x='0' y='0' z='1.5'/><float name='radius' value='0.5'/>"
      "<ref name='interior' id='fog'/></shape>");
  ASSERT_TRUE(fogged->features().medium_walk);
  const auto a = test::render_scene(fogged, 1).resolve(), b = test::render_scene(scene_with(""), 1).resolve();
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-5f) << i;
  EXPECT_FLOAT_EQ(a[4 * 4 + 2], 0.3f);  // the centre's albedo, behind the ball
}

TEST(AovIntegrator, UnknownKindIsAnError) {
  EXPECT_THAT(test::load_error("<scene version='3.0.0'>\n<integrator type='aov'>\n"
                               "<string name='aovs' value='a:albedo,b:curvature'/></integrator></scene>"),
              testing::HasSubstr("test.xml:3: parameter 'aovs' of integrator 'aov': unknown kind 'curvature'"));
}

// dp_du and dp_dv against the positions and (u, v) of neighbouring pixels
// on one plane (an affine mapping: p(x+1) - p(x) = dp_du du + dp_dv dv
// exactly); prim_index by which of a quad's two triangles a corner pixel
// meets; shape_index by the shape's place in the file.
TEST(AovIntegrator, TangentsAndIndices) {
  const auto mesh = std::filesystem::temp_directory_path() / "caustica_aov_quad.obj";
  // Face 0 is the lower-right half of the quad, face 1 the upper-left.
  std::ofstream(mesh) << "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3\nf 1 3 4\n";
  const std::string camera =
      "<sensor type='perspective'><float name='fov' value='30'/><transform name='to_world'><lookat origin='0, 0, 3' "
      "target='0, 0, 0'/></transform><film type='hdrfilm'><integer name='width' value='5'/><integer name='height' "
      "value='5'/><rfilter type='box'/></film><sampler type='independent'><integer name='sample_count' "
      "value='1'/></sampler></sensor>";
  const auto plane = test::scene_from_xml(
      "<scene version='3.0.0'><integrator type='aov'><string name='aovs' value='p:position,t:uv,du:dp_du,"
      "dv:dp_dv'/></integrator>" +
      camera +
      "<shape type='rectangle'><transform name='to_world'><scale x='2' y='1.5'/><rotate z='1' angle='20'/>"
      "</transform></shape></scene>");
  ASSERT_EQ(plane.integrator->channels().size(), 11u);
  EXPECT_EQ(plane.integrator->channels()[5], "du.X");
  const auto img = test::render_scene(plane, 1).resolve();
  const auto at = [&](int x, int y) { return &img[(y * 5 + x) * 11]; };
  for (const auto& [x0, y0, x1, y1] : {std::array{2, 2, 3, 2}, std::array{2, 2, 2, 1}, std::array{1, 3, 3, 1}}) {
    const float *a = at(x0, y0), *b = at(x1, y1);
    const float du = b[3] - a[3], dv = b[4] - a[4];
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(b[c] - a[c], a[5 + c] * du + a[8 + c] * dv, 1e-4f) << x1 << " " << y1 << " axis " << c;
  }
  const auto quad = test::scene_from_xml(
      "<scene version='3.0.0'><integrator type='aov'><string name='aovs' value='i:prim_index,s:shape_index'/>"
      "</integrator>" +
      camera +
      "<shape type='sphere'><point name='center' x='0' y='0' z='-50'/></shape><shape type='obj'>"
      "<string name='filename' value='" +
      mesh.string() + "'/></shape></scene>");
  const auto indices = test::render_scene(quad, 1).resolve();
  EXPECT_EQ(indices[(4 * 5 + 4) * 2], 0);  // the lower-right corner: face 0
  EXPECT_EQ(indices[(0 * 5 + 0) * 2], 1);  // the upper-left corner: face 1
  for (int p = 0; p < 25; ++p) EXPECT_EQ(indices[p * 2 + 1], 1) << p;
}

// duv_dx and duv_dy against the (u, v) the neighbouring pixels see: with
// every ray through its pixel's centre (a box filter of radius 1e-6), the
// neighbour's ray meets the plane where that pixel's hit is, and on a
// plane (u, v) is affine in position, so duv_dx at x is uv(x + 1) - uv(x).
// A perspective camera (whose steps vary across the image) and a tilted,
// rotated, unevenly scaled rectangle; off the plane, zeros.
TEST(AovIntegrator, UvStepsToTheNextPixel) {
  constexpr int kSize = 7, kChannels = 6;
  const auto scene = test::scene_from_xml(
      "<scene version='3.0.0'><integrator type='aov'><string name='aovs' value='t:uv,x:duv_dx,y:duv_dy'/>"
      "</integrator><sensor type='perspective'><float name='fov' value='40'/><transform name='to_world'>"
      "<lookat origin='0.3, -0.5, 3' target='0, 0, 0'/></transform><film type='hdrfilm'><integer name='width' "
      "value='7'/><integer name='height' value='7'/><rfilter type='box'><float name='radius' value='1e-6'/>"
      "</rfilter></film></sensor><shape type='rectangle'><transform name='to_world'><scale x='3' y='1.2'/>"
      "<rotate z='1' angle='25'/><rotate x='1' angle='30'/></transform></shape></scene>");
  ASSERT_EQ(scene.integrator->channels().size(), size_t(kChannels));
  EXPECT_EQ(scene.integrator->channels()[2], "x.U");
  EXPECT_EQ(scene.integrator->channels()[5], "y.V");
  const auto img = test::render_scene(scene, 1).resolve();
  const auto at = [&](int x, int y) { return &img[(y * kSize + x) * kChannels]; };
  int checked = 0;
  for (int y = 0; y + 1 < kSize; ++y)
    for (int x = 0; x + 1 < kSize; ++x) {
      const float *here = at(x, y), *right = at(x + 1, y), *below = at(x, y + 1);
      const bool hits = here[0] != 0 && right[0] != 0 && below[0] != 0;
      if (!hits) continue;
      ++checked;
      for (int c = 0; c < 2; ++c) {
        EXPECT_NEAR(here[2 + c], right[c] - here[c], 2e-5f) << x << ", " << y << " x channel " << c;
        EXPECT_NEAR(here[4 + c], below[c] - here[c], 2e-5f) << x << ", " << y << " y channel " << c;
      }
    }
  EXPECT_GE(checked, 12);
  // A pixel that misses: zeros.
  const auto sky = test::scene_from_xml(
      "<scene version='3.0.0'><integrator type='aov'><string name='aovs' value='x:duv_dx'/></integrator>"
      "<sensor type='perspective'><film type='hdrfilm'><integer name='width' value='2'/><integer name='height' "
      "value='2'/></film></sensor></scene>");
  for (float v : test::render_scene(sky, 1).resolve()) EXPECT_EQ(v, 0.0f);
}

// A nested path tracer writes its image, prefixed by its name, before the
// layers: the same image, bit for bit, as path alone with the same seed
// (the layers draw no numbers).
TEST(AovIntegrator, NestedIntegratorsRenderAlong) {
  const std::string rest =
      "<sensor type='perspective'><transform name='to_world'><lookat origin='0, 1, 4' target='0, 0, 0'/>"
      "</transform><film type='hdrfilm'><integer name='width' value='6'/><integer name='height' value='4'/>"
      "</film></sensor><shape type='sphere'/><shape type='rectangle'><transform name='to_world'><scale value='3'/>"
      "<rotate x='1' angle='-90'/><translate y='-1'/></transform></shape><emitter type='constant'/></scene>";
  const auto along = test::scene_from_xml(
      "<scene version='3.0.0'><integrator type='aov'><string name='aovs' value='d:depth'/>"
      "<integrator type='path' name='my_image'><integer name='max_depth' value='3'/></integrator></integrator>" +
      rest);
  EXPECT_THAT(along.integrator->channels(), testing::ElementsAre("my_image.R", "my_image.G", "my_image.B", "d.T"));
  const auto alone = test::scene_from_xml(
      "<scene version='3.0.0'><integrator type='path'><integer name='max_depth' value='3'/></integrator>" + rest);
  const auto layers = test::scene_from_xml(
      "<scene version='3.0.0'><integrator type='aov'><string name='aovs' value='d:depth'/></integrator>" + rest);
  const auto a = test::render_scene(along, 8, 5).resolve(), b = test::render_scene(alone, 8, 5).resolve(),
             d = test::render_scene(layers, 8, 5).resolve();
  ASSERT_EQ(a.size() / 4, b.size() / 3);
  double sum = 0;
  for (size_t p = 0; p < b.size() / 3; ++p) {
    for (int c = 0; c < 3; ++c) EXPECT_EQ(a[p * 4 + c], b[p * 3 + c]) << p;
    EXPECT_EQ(a[p * 4 + 3], d[p]) << p;
    sum += b[p * 3];
  }
  EXPECT_GT(sum, 0);
}

TEST(AovIntegrator, NestedIntegratorsThatCannotBeAreRefused) {
  const auto error = [](const std::string& nested) {
    return test::load_error("<scene version='3.0.0'>\n<integrator type='aov'>\n" + nested + "</integrator></scene>");
  };
  EXPECT_THAT(error("<integrator type='bdpt' name='b'/>"),
              testing::HasSubstr("test.xml:2: a nested integrator of aov must estimate pixel by pixel from the camera "
                                 "(path, volpath, direct, guided_path, photon or radiosity), which 'bdpt' does not"));
  EXPECT_THAT(error("<integrator type='path'/>"),
              testing::HasSubstr("test.xml:2: a nested integrator of aov needs a name (name=\"...\")"));
  EXPECT_THAT(error("<integrator type='path' name='a'/><integrator type='direct' name='a'/>"),
              testing::HasSubstr("two nested integrators of aov are named 'a'"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
