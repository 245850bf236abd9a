// References are resolved over the whole scene, whatever the order of the
// objects: Mitsuba reads the whole tree before it builds anything, and its
// own data files declare an area emitter after the shapes that refer to it.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/lights/emitter.h"
#include "core/loader/scene_loader.h"
#include "core/shapes/shape.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using testing::HasSubstr;

const std::string kHead =
    "<scene version='3.0.0'><sensor type='perspective'><film type='hdrfilm'><integer name='width' value='8'/>"
    "<integer name='height' value='8'/></film><transform name='to_world'><lookat origin='0, 0, 4' target='0, 0, 0' "
    "up='0, 1, 0'/></transform></sensor><shape type='sphere'><float name='radius' value='0.5'/></shape>\n";
const std::string kLight = "<emitter type='area' id='light'><rgb name='radiance' value='3, 2, 1'/></emitter>\n";
const std::string kLamp = "<shape type='rectangle'><transform name='to_world'><translate z='1.5'/></transform>";

std::vector<float> pixels(const LoadedScene& scene) { return test::render_scene(scene, 4, 7, 1).resolve(); }

// The lamp's emitter nested in it, as caustica's own scenes write it.
LoadedScene nested() {
  return test::scene_from_xml(kHead + kLamp + "<emitter type='area'><rgb name='radiance' value='3, 2, 1'/></emitter>" +
                              "</shape></scene>");
}

void expect_the_lamp_emits(const LoadedScene& scene) {
  ASSERT_EQ(scene->emitters().size(), 1u);
  int lamps = 0;
  for (const auto& shape : scene->shapes()) lamps += shape->emitter() == scene->emitters()[0].get();
  EXPECT_EQ(lamps, 1);
}

TEST(ReferenceOrder, AnAreaEmitterDeclaredAfterTheShapeReferringToIt) {
  const auto scene = test::scene_from_xml(kHead + kLamp + "<ref id='light'/></shape>\n" + kLight + "</scene>");
  expect_the_lamp_emits(scene);
  EXPECT_EQ(pixels(scene), pixels(nested()));
}

TEST(ReferenceOrder, AnAreaEmitterDeclaredBeforeTheShapeReferringToIt) {
  const auto scene = test::scene_from_xml(kHead + kLight + kLamp + "<ref id='light'/></shape>\n</scene>");
  expect_the_lamp_emits(scene);
  EXPECT_EQ(pixels(scene), pixels(nested()));
}

// mitsuba-data's cbox-rgb.xml: the shapes come from an included file, the
// emitter they refer to is declared after the include.
TEST(ReferenceOrder, AReferenceFromAnIncludedFileToALaterObject) {
  const auto dir = std::filesystem::temp_directory_path() / "caustica_reference_order_test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "shapes.xml") << "<scene version='3.0.0'>" << kLamp << "<ref id='light'/></shape></scene>";
  std::ofstream(dir / "main.xml") << kHead << "<include filename='shapes.xml'/>\n" << kLight << "</scene>";
  const LoadedScene scene = load_scene(dir / "main.xml");
  expect_the_lamp_emits(scene);
  EXPECT_EQ(pixels(scene), pixels(nested()));
}

TEST(ReferenceOrder, AnAreaEmitterNoShapeRefersToIsRefused) {
  EXPECT_THAT(test::load_error(kHead + kLamp + "</shape>\n" + kLight + "</scene>", "alone.xml"),
              HasSubstr("alone.xml:3: an area emitter must be nested in a shape or referenced by one"));
}

TEST(ReferenceOrder, AnAreaEmitterTwoShapesReferToIsRefused) {
  EXPECT_THAT(test::load_error(
                  kHead + kLight + kLamp + "<ref id='light'/></shape>\n" + kLamp + "<ref id='light'/></shape></scene>",
                  "twice.xml"),
              HasSubstr("twice.xml:2: an area emitter can belong to one shape only"));
}

TEST(ReferenceOrder, ACycleOfReferencesIsNamedIdById) {
  const std::string xml =
      "<scene version='3.0.0'>\n<bsdf type='twosided' id='a'><ref id='b'/></bsdf>\n"
      "<bsdf type='twosided' id='b'><ref id='c'/></bsdf>\n<bsdf type='twosided' id='c'><ref id='a'/></bsdf>\n"
      "<shape type='sphere'><ref id='a'/></shape></scene>";
  EXPECT_THAT(test::load_error(xml, "cycle.xml"),
              HasSubstr("cycle.xml:2: references form a cycle: 'a' -> 'b' -> 'c' -> 'a'"));
}

TEST(ReferenceOrder, AnObjectReferringToItselfIsACycleOfOne) {
  EXPECT_THAT(test::load_error("<scene version='3.0.0'>\n<bsdf type='twosided' id='a'><ref id='a'/></bsdf></scene>",
                               "self.xml"),
              HasSubstr("self.xml:2: references form a cycle: 'a' -> 'a'"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
