#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/test_scenes.h"

namespace caustica {
namespace {

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

}  // namespace
}  // namespace caustica
