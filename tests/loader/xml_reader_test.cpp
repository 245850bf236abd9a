#include "core/loader/xml_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Pair;

// Returns what() of the SceneError `f` throws, failing the test if it throws none.
template <typename F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const SceneError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected a SceneError";
  return "";
}

// A fresh directory per test, so include tests never see each other's files.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() / "caustica_xml_reader_test" / info->name();
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }

  fs::path write(const std::string& name, const std::string& text) const {
    fs::path file = path_ / name;
    fs::create_directories(file.parent_path());
    std::ofstream(file) << text;
    return file;
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

TEST(XmlReader, NodesCarryFileAndLine) {
  XmlNode root = read_scene_xml_string(
      "<?xml version='1.0'?>\n"
      "<scene version='3.0.0'>\n"
      "  <!-- a comment\n spanning lines -->\n"
      "  <shape type='sphere'>\n"
      "    <float name='radius' value='2'/>\n"
      "  </shape>\n"
      "</scene>\n",
      "scene.xml");
  EXPECT_EQ(root.tag, "scene");
  EXPECT_EQ(root.where.file, "scene.xml");
  EXPECT_EQ(root.where.line, 2);
  ASSERT_EQ(root.children.size(), 1u);  // the comment is dropped
  const XmlNode& shape = root.children[0];
  EXPECT_EQ(shape.tag, "shape");
  EXPECT_EQ(shape.where.line, 5);
  ASSERT_EQ(shape.children.size(), 1u);
  EXPECT_EQ(shape.children[0].where.line, 6);
  EXPECT_EQ(shape.children[0].where.str(), "scene.xml:6");
}

TEST(XmlReader, AttributesKeepFileOrder) {
  XmlNode root = read_scene_xml_string("<scene><lookat target='0,0,0' origin='1,2,3' up='0,1,0'/></scene>", "s.xml");
  ASSERT_EQ(root.children.size(), 1u);
  EXPECT_THAT(root.children[0].attributes,
              ::testing::ElementsAre(Pair("target", "0,0,0"), Pair("origin", "1,2,3"), Pair("up", "0,1,0")));
}

TEST(XmlReader, DefaultsAreSubstitutedAndRemoved) {
  const char* text =
      "<scene version='3.0.0'>\n"
      "  <integrator type='$integrator'><integer name='max_depth' value='$depth'/></integrator>\n"
      "  <default name='integrator' value='path'/>\n"
      "  <default name='depth' value='8'/>\n"
      "</scene>\n";
  XmlNode root = read_scene_xml_string(text, "s.xml");
  ASSERT_EQ(root.children.size(), 1u);
  const XmlNode& integrator = root.children[0];
  EXPECT_EQ(*integrator.attribute("type"), "path");
  EXPECT_EQ(*integrator.children[0].attribute("value"), "8");

  // -D wins over <default>.
  root = read_scene_xml_string(text, "s.xml", {{"depth", "3"}, {"unused", "x"}});
  EXPECT_EQ(*root.children[0].attribute("type"), "path");
  EXPECT_EQ(*root.children[0].children[0].attribute("value"), "3");
}

TEST(XmlReader, DefaultsMayReferToEarlierDefaults) {
  XmlNode root = read_scene_xml_string(
      "<scene><default name='dir' value='meshes'/><default name='file' value='$dir/a.obj'/>"
      "<string name='filename' value='$file'/></scene>",
      "s.xml");
  EXPECT_EQ(*root.children[0].attribute("value"), "meshes/a.obj");
}

TEST(XmlReader, EmbeddedReferences) {
  XmlNode root = read_scene_xml_string(
      "<scene><default name='name' value='bunny'/>"
      "<string name='filename' value='meshes/$name.obj'/>"
      "<string name='other' value='$name$name_2 costs $5'/></scene>",
      "s.xml", {{"name_2", "X"}});
  EXPECT_EQ(*root.children[0].attribute("value"), "meshes/bunny.obj");
  // The longest name is taken, and a '$' not followed by a name is kept.
  EXPECT_EQ(*root.children[1].attribute("value"), "bunnyX costs $5");
}

TEST(XmlReader, UndefinedReferenceIsAnErrorAtItsLine) {
  std::string message =
      error_of([] { read_scene_xml_string("<scene>\n\n  <float name='x' value='$spp'/>\n</scene>", "dir/s.xml"); });
  EXPECT_EQ(message, "dir/s.xml:3: undefined parameter '$spp' (define it with <default> or -D spp=value)");
}

TEST(XmlReader, DefaultWithoutValueIsAnError) {
  EXPECT_THAT(error_of([] { read_scene_xml_string("<scene>\n<default name='a'/>\n</scene>", "s.xml"); }),
              HasSubstr("s.xml:2: <default> needs both"));
}

TEST(XmlReader, MalformedXmlReportsLine) {
  std::string message =
      error_of([] { read_scene_xml_string("<scene>\n  <shape type='sphere'>\n  </shap>\n</scene>\n", "bad.xml"); });
  EXPECT_THAT(message, ::testing::StartsWith("bad.xml:3: malformed XML: "));
}

TEST(XmlReader, WrongRoot) {
  EXPECT_EQ(error_of([] { read_scene_xml_string("\n<shape type='sphere'/>", "s.xml"); }),
            "s.xml:2: root element must be <scene>, found <shape>");
}

TEST(XmlReader, MissingFile) {
  TempDir dir;
  fs::path missing = dir.path() / "nope.xml";
  std::string message = error_of([&] { read_scene_xml(missing); });
  EXPECT_THAT(message, HasSubstr("cannot open scene file"));
  EXPECT_THAT(message, HasSubstr(missing.string()));
}

// /dev/zero would be read forever.
TEST(XmlReader, IncludesMustBeRegularFiles) {
  EXPECT_EQ(error_of([] { read_scene_xml_string("<scene>\n<include filename='/dev/zero'/>\n</scene>", "s.xml"); }),
            "s.xml:2: the included file '/dev/zero' is not a regular file");
}

TEST(XmlReader, ReportsTheDefinesNoReferenceUsed) {
  std::vector<std::string> unused;
  read_scene_xml_string("<scene><default name='a' value='$b'/><float name='x' value='$a'/></scene>", "s.xml",
                        {{"a", "1"}, {"b", "2"}, {"c", "3"}}, &unused);
  EXPECT_EQ(unused, std::vector<std::string>{"c"});
}

TEST(XmlReader, ReadsFromFile) {
  TempDir dir;
  fs::path file = dir.write("scene.xml", "<scene>\n<sensor type='perspective'/>\n</scene>\n");
  XmlNode root = read_scene_xml(file);
  ASSERT_EQ(root.children.size(), 1u);
  EXPECT_EQ(root.children[0].where.file, file.string());
  EXPECT_EQ(root.children[0].where.line, 2);
}

TEST(XmlReader, IncludeSplicesChildrenWithTheirOwnLines) {
  TempDir dir;
  dir.write("parts/shapes.xml",
            "<scene version='3.0.0'>\n"
            "  <default name='radius' value='1'/>\n"
            "  <shape type='sphere'><float name='radius' value='$radius'/></shape>\n"
            "  <shape type='$second'/>\n"
            "</scene>\n");
  fs::path main = dir.path() / "main.xml";
  XmlNode root = read_scene_xml_string(
      "<scene version='3.0.0'>\n"
      "  <integrator type='path'/>\n"
      "  <include filename='parts/shapes.xml'/>\n"
      "  <sensor type='perspective'/>\n"
      "</scene>\n",
      main, {{"second", "cube"}});
  ASSERT_EQ(root.children.size(), 4u);
  EXPECT_EQ(root.children[0].tag, "integrator");
  EXPECT_EQ(root.children[1].tag, "shape");
  EXPECT_EQ(root.children[1].where.file, (dir.path() / "parts/shapes.xml").string());
  EXPECT_EQ(root.children[1].where.line, 3);
  EXPECT_EQ(*root.children[1].children[0].attribute("value"), "1");
  EXPECT_EQ(*root.children[2].attribute("type"), "cube");  // the included file sees -D
  EXPECT_EQ(root.children[2].where.line, 4);
  EXPECT_EQ(root.children[3].tag, "sensor");
  EXPECT_EQ(root.children[3].where.file, main.string());
  EXPECT_EQ(root.children[3].where.line, 4);
}

TEST(XmlReader, MissingIncludeIsAnErrorAtTheInclude) {
  TempDir dir;
  std::string message = error_of(
      [&] { read_scene_xml_string("<scene>\n<include filename='gone.xml'/>\n</scene>", dir.path() / "main.xml"); });
  EXPECT_THAT(message, ::testing::StartsWith((dir.path() / "main.xml").string() + ":2: "));
  EXPECT_THAT(message, HasSubstr("gone.xml"));
}

TEST(XmlReader, IncludedFileMustBeAScene) {
  TempDir dir;
  dir.write("part.xml", "<shape type='cube'/>");
  EXPECT_THAT(error_of([&] {
                read_scene_xml_string("<scene><include filename='part.xml'/></scene>", dir.path() / "main.xml");
              }),
              HasSubstr("root element must be <scene>, found <shape>"));
}

TEST(XmlReader, IncludeCycleIsAnError) {
  TempDir dir;
  dir.write("a.xml", "<scene>\n<include filename='b.xml'/>\n</scene>");
  dir.write("b.xml", "<scene>\n\n<include filename='a.xml'/>\n</scene>");
  std::string message = error_of([&] { read_scene_xml(dir.path() / "a.xml"); });
  EXPECT_THAT(message, ::testing::StartsWith((dir.path() / "b.xml").string() + ":3: include cycle"));

  // A file including itself through a differently spelled path.
  dir.write("self.xml", "<scene><include filename='./self.xml'/></scene>");
  EXPECT_THAT(error_of([&] { read_scene_xml(dir.path() / "self.xml"); }), HasSubstr("include cycle"));
}

TEST(XmlReader, UpgradesMitsuba0xFiles) {
  XmlNode root = read_scene_xml_string(
      "<scene version='0.6.0'>\n"
      "  <integrator type='path'><integer name='maxDepth' value='5'/><integer name='rrDepth' value='3'/>"
      "<boolean name='hideEmitters' value='true'/></integrator>\n"
      "  <sensor type='perspective'>\n"
      "    <string name='fovAxis' value='x'/>\n"
      "    <transform name='toWorld'><lookAt origin='0,0,1' target='0,0,0' up='0,1,0'/></transform>\n"
      "    <sampler type='independent'><integer name='sampleCount' value='16'/></sampler>\n"
      "    <film type='ldrfilm'><float name='gamma' value='2.2'/><integer name='width' value='8'/></film>\n"
      "  </sensor>\n"
      "  <bsdf type='dielectric'><float name='intIOR' value='1.5'/><float name='extIOR' value='1'/>"
      "<srgb name='specularReflectance' value='0.5'/></bsdf>\n"
      "</scene>\n",
      "old.xml");
  const XmlNode& integrator = root.children[0];
  EXPECT_EQ(*integrator.children[0].attribute("name"), "max_depth");
  EXPECT_EQ(*integrator.children[1].attribute("name"), "rr_depth");
  EXPECT_EQ(*integrator.children[2].attribute("name"), "hide_emitters");
  const XmlNode& sensor = root.children[1];
  EXPECT_EQ(*sensor.children[0].attribute("name"), "fov_axis");
  EXPECT_EQ(*sensor.children[1].attribute("name"), "to_world");
  EXPECT_EQ(sensor.children[1].children[0].tag, "lookat");
  EXPECT_EQ(sensor.children[1].children[0].where.line, 5);
  EXPECT_EQ(*sensor.children[2].children[0].attribute("name"), "sample_count");
  // ldrfilm stays a film of its own, its display settings with it.
  EXPECT_EQ(*sensor.children[3].attribute("type"), "ldrfilm");
  ASSERT_EQ(sensor.children[3].children.size(), 2u);
  EXPECT_EQ(*sensor.children[3].children[0].attribute("name"), "gamma");
  const XmlNode& bsdf = root.children[2];
  EXPECT_EQ(*bsdf.children[0].attribute("name"), "int_ior");
  EXPECT_EQ(*bsdf.children[1].attribute("name"), "ext_ior");
  EXPECT_EQ(bsdf.children[2].tag, "rgb");
  EXPECT_EQ(*bsdf.children[2].attribute("name"), "specular_reflectance");
}

TEST(XmlReader, LeavesCurrentFilesAlone) {
  for (const char* version : {"version='2.0.0'", "version='3.5.1'", ""}) {
    XmlNode root = read_scene_xml_string(
        std::string("<scene ") + version + "><film type='ldrfilm'><srgb name='sampleCount' value='1'/></film></scene>",
        "s.xml");
    EXPECT_EQ(*root.children[0].attribute("type"), "ldrfilm") << version;
    EXPECT_EQ(root.children[0].children[0].tag, "srgb") << version;
    EXPECT_EQ(*root.children[0].children[0].attribute("name"), "sampleCount") << version;
  }
}

TEST(XmlReader, IncludedFileUpgradesByItsOwnVersion) {
  TempDir dir;
  dir.write("old.xml", "<scene version='0.5.0'><float name='nearClip' value='1'/></scene>");
  XmlNode root = read_scene_xml_string(
      "<scene version='3.0.0'><include filename='old.xml'/><float name='farClip' value='1'/></scene>",
      dir.path() / "main.xml");
  EXPECT_EQ(*root.children[0].attribute("name"), "near_clip");
  EXPECT_EQ(*root.children[1].attribute("name"), "farClip");
}

TEST(XmlReader, BadVersionIsAnError) {
  for (const char* version : {"three", "0.6", "1.2.3.4", "1..0", ""}) {
    EXPECT_THAT(error_of([&] { read_scene_xml_string("\n<scene version='" + std::string(version) + "'/>", "s.xml"); }),
                HasSubstr("s.xml:2: invalid version"))
        << version;
  }
}

TEST(CamelToSnake, Examples) {
  EXPECT_EQ(camel_to_snake("toWorld"), "to_world");
  EXPECT_EQ(camel_to_snake("sampleCount"), "sample_count");
  EXPECT_EQ(camel_to_snake("maxDepth"), "max_depth");
  EXPECT_EQ(camel_to_snake("intIOR"), "int_ior");
  EXPECT_EQ(camel_to_snake("extIOR"), "ext_ior");
  EXPECT_EQ(camel_to_snake("fovAxis"), "fov_axis");
  EXPECT_EQ(camel_to_snake("specularReflectance"), "specular_reflectance");
  EXPECT_EQ(camel_to_snake("rrDepth"), "rr_depth");
  EXPECT_EQ(camel_to_snake("hideEmitters"), "hide_emitters");
  EXPECT_EQ(camel_to_snake("nearClip"), "near_clip");
  EXPECT_EQ(camel_to_snake("focusDistance"), "focus_distance");
  EXPECT_EQ(camel_to_snake("IORValue"), "ior_value");
  EXPECT_EQ(camel_to_snake("already_snake"), "already_snake");
  EXPECT_EQ(camel_to_snake("radius"), "radius");
  EXPECT_EQ(camel_to_snake(""), "");
}

// Ten thousand nested elements would exhaust the stack of a recursive
// reader; it stops at the limit with the element's line.
TEST(XmlReader, DeepNestingIsRefused) {
  std::string text = "<scene>\n";
  for (int i = 0; i < 10000; ++i) text += "<a>";
  for (int i = 0; i < 10000; ++i) text += "</a>";
  text += "</scene>";
  EXPECT_EQ(error_of([&] { read_scene_xml_string(text, "deep.xml"); }),
            "deep.xml:2: <a> is nested more than 64 elements deep");
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
