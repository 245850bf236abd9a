// Media in scene files as Mitsuba 3 writes them: <medium> and <phase>
// elements, a shape's interior and exterior (referenced or nested), the
// sensor's medium, the null boundary a shape without a material becomes,
// and what the scene analysis reports.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/bsdf/bsdf.h"
#include "core/media/medium.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using testing::HasSubstr;

const std::string kFog = "<medium type='homogeneous' id='fog'><float name='sigma_t' value='2'/></medium>";

TEST(MediaLoading, ShapesTakeInteriorAndExteriorMedia) {
  const auto scene = test::scene_from_xml(
      "<scene version='3.0.0'>" + kFog +
      "<shape type='sphere'><ref name='interior' id='fog'/>"
      "<medium type='homogeneous' name='exterior'><rgb name='sigma_t' value='1, 2, 3'/></medium></shape>"
      "<shape type='rectangle'/></scene>");
  const Shape& ball = *scene->shapes()[0];
  ASSERT_TRUE(ball.bounds_media());
  EXPECT_EQ(ball.interior()->plugin_name(), "homogeneous");
  EXPECT_TRUE(ball.exterior()->is_chromatic());
  EXPECT_FALSE(ball.interior()->is_chromatic());
  // Without a material it is the media's index-matched boundary ...
  EXPECT_EQ(ball.lobes(), kNull);
  // ... while a shape bounding none stays grey diffuse, as in Mitsuba.
  EXPECT_FALSE(scene->shapes()[1]->bounds_media());
  EXPECT_EQ(scene->shapes()[1]->lobes(), kDiffuseReflection);
  const SceneFeatures& f = scene->features();
  EXPECT_EQ(f.media, 2);
  EXPECT_EQ(f.chromatic_media, 1);
  EXPECT_FALSE(f.camera_in_medium);
  EXPECT_TRUE(f.medium_walk);
  EXPECT_THAT(describe(f), HasSubstr("media: 2 (2 homogeneous, 0 heterogeneous; 1 with extinction differing"));
}

TEST(MediaLoading, TheSensorTakesAnyNestedMedium) {
  for (const std::string& medium : {std::string("<ref id='fog'/>"), std::string("<ref name='medium' id='fog'/>")}) {
    const auto scene = test::scene_from_xml("<scene version='3.0.0'>" + kFog + "<sensor type='perspective'>" + medium +
                                            "</sensor></scene>");
    ASSERT_TRUE(scene->sensor().medium()) << medium;
    EXPECT_TRUE(scene->features().camera_in_medium);
  }
}

TEST(MediaLoading, AScatteringSurfaceKeepsItsMaterialAroundAMedium) {
  const auto scene = test::scene_from_xml("<scene version='3.0.0'>" + kFog +
                                          "<shape type='sphere'><bsdf type='dielectric'/><ref name='interior' "
                                          "id='fog'/></shape></scene>");
  EXPECT_EQ(scene->shapes()[0]->lobes(), kDeltaReflection | kDeltaTransmission);
}

TEST(MediaLoading, ScenesWithoutMediaWalkWithoutThem) {
  const auto scene = test::scene_from_xml("<scene version='3.0.0'><shape type='sphere'/></scene>");
  EXPECT_EQ(scene->features().media, 0);
  EXPECT_FALSE(scene->features().medium_walk);
  EXPECT_THAT(describe(scene->features()), HasSubstr("media: none"));
  // A null surface alone still needs the walk that steps through it.
  const auto null_only =
      test::scene_from_xml("<scene version='3.0.0'><shape type='sphere'><bsdf type='null'/></shape></scene>");
  EXPECT_TRUE(null_only->features().medium_walk);
}

TEST(MediaLoading, BadMediaAreErrors) {
  EXPECT_THAT(test::load_error("<scene version='3.0.0'>\n<shape type='sphere'>\n<medium type='homogeneous'/></shape>"
                               "</scene>",
                               "bad.xml"),
              HasSubstr("bad.xml:3: shape 'sphere' takes a nested <medium> only as a parameter: name it "
                        "(name=\"...\"): interior, exterior"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'>\n<medium type='fog' id='m'/></scene>", "bad.xml"),
              HasSubstr("bad.xml:2: unknown medium type 'fog' (available: heterogeneous, homogeneous)"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'>\n<shape type='sphere'>\n<ref name='interior' id='none'/>"
                               "</shape></scene>",
                               "bad.xml"),
              HasSubstr("bad.xml:3: reference to undefined id 'none'"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'>\n<bsdf type='diffuse' id='white'/>\n<shape type='sphere'>\n"
                               "<ref name='interior' id='white'/></shape></scene>",
                               "bad.xml"),
              HasSubstr("bad.xml:4: parameter 'interior' of shape 'sphere' must be medium, not bsdf"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
