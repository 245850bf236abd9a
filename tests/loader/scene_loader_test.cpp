#include "core/loader/scene_loader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <tuple>

#include "core/bsdf/bsdf.h"
#include "core/errors/interrupted.h"
#include "core/lights/emitter.h"
#include "core/math/constants.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using testing::HasSubstr;
using testing::StartsWith;

const std::string kCornellMeshes = std::string(CAUSTICA_SOURCE_DIR) + "/scenes/meshes/cornell/";

std::filesystem::path write_temp(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::temp_directory_path() / "caustica_scene_loader_test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / name) << text;
  return dir / name;
}

TEST(SceneLoader, EveryElementOfTheSubset) {
  const auto ply = write_temp("tri.ply",
                              "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                              "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                              "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  const std::string xml = R"(<scene version="3.0.0">
    <default name="w" value="32"/>
    <integrator type="path">
      <integer name="max_depth" value="$depth"/>
      <boolean name="hide_emitters" value="true"/>
    </integrator>
    <sensor type="perspective">
      <float name="fov" value="45"/>
      <string name="fov_axis" value="y"/>
      <transform name="to_world">
        <lookat origin="0, 0, 5" target="0, 0, 0" up="0, 1, 0"/>
      </transform>
      <sampler type="independent"><integer name="sample_count" value="3"/></sampler>
      <film type="hdrfilm">
        <integer name="width" value="$w"/><integer name="height" value="24"/>
        <string name="component_format" value="float32"/>
        <rfilter type="tent"><float name="radius" value="1.5"/></rfilter>
      </film>
    </sensor>
    <bsdf type="diffuse" id="grey"><spectrum name="reflectance" value="0.4"/></bsdf>
    <bsdf type="twosided" id="sheet"><bsdf type="diffuse"><rgb name="reflectance" value="0.1, 0.2, 0.3"/></bsdf></bsdf>
    <shape type="obj">
      <string name="filename" value=")" +
                          kCornellMeshes + R"(floor.obj"/>
      <transform name="to_world"><scale value="0.001"/><rotate y="1" angle="30"/><translate x="1"/></transform>
      <ref id="grey"/>
    </shape>
    <shape type="ply"><string name="filename" value=")" +
                          ply.string() + R"("/><ref id="sheet"/></shape>
    <shape type="rectangle">
      <transform name="to_world"><matrix value="1 0 0 0  0 1 0 2  0 0 1 0  0 0 0 1"/></transform>
      <emitter type="area"><rgb name="radiance" value="1, 2, 3"/></emitter>
    </shape>
    <shape type="cube"><ref id="grey"/></shape>
    <shape type="sphere"><point name="center" x="0" y="3" z="0"/><float name="radius" value="0.5"/></shape>
    <shape type="disk"><boolean name="flip_normals" value="true"/></shape>
    <emitter type="point"><point name="position" value="0, 4, 0"/><rgb name="intensity" value="5"/></emitter>
    <emitter type="constant"><rgb name="radiance" value="0.1"/></emitter>
  </scene>)";
  const auto scene = load_scene_string(xml, "all.xml", {{"depth", "7"}});
  EXPECT_EQ(scene->shapes().size(), 6u);
  EXPECT_EQ(scene->emitters().size(), 3u);
  EXPECT_EQ(scene->infinite_emitters().size(), 1u);
  EXPECT_EQ(scene->sensor().film()->width(), 32);
  EXPECT_EQ(scene->sensor().film()->height(), 24);
  EXPECT_FALSE(scene->sensor().film()->half_float());
  EXPECT_FLOAT_EQ(scene->sensor().film()->filter().radius(), 1.5f);
  EXPECT_EQ(scene->sensor().sampler()->sample_count(), 3u);
  EXPECT_EQ(scene.integrator->describe(),
            "path max_depth=7 rr_depth=5 rr_max_survival=0.950000 rr_threshold=0.100000 hide_emitters=true");
  EXPECT_EQ(scene->shapes()[0]->bsdf(), scene->shapes()[3]->bsdf());  // one object through ref
  EXPECT_EQ(scene->shapes()[1]->bsdf()->lobes(), kDiffuseReflection);
  EXPECT_NE(scene->shapes()[2]->emitter(), nullptr);
  // The floor's centre (0.2764, 0, 0.2796) after the scale, a rotation by 30
  // degrees about y and the move along x.
  const auto hit = scene->intersect({scene->render_point({1.3792, 1, 0.1039}), {0, -1, 0}});
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 1, 1e-5f);
}

// Exported scenes often name nested objects; where the plugin has no
// parameter of that name the object is an ordinary child.
TEST(SceneLoader, NamedNestedObjectsAreChildren) {
  const auto scene = load_scene_string(
      "<scene version='3.0.0'><bsdf type='diffuse' id='m'/><shape type='cube'><ref id='m' name='bsdf'/></shape>"
      "<shape type='sphere'><bsdf type='diffuse' name='surface'/></shape></scene>",
      "named.xml");
  EXPECT_EQ(scene->shapes().size(), 2u);
}

TEST(SceneLoader, DirectSampleCountsDefaultToShadingSamples) {
  const auto scene = load_scene_string(
      "<scene version='3.0.0'><integrator type='direct'><integer name='shading_samples' value='3'/>"
      "<integer name='bsdf_samples' value='2'/></integrator></scene>",
      "direct.xml");
  EXPECT_THAT(scene.integrator->describe(), StartsWith("direct emitter_samples=3 bsdf_samples=2"));
}

TEST(SceneLoader, TonemapElementChoosesTheDevelopment) {
  const auto scene = load_scene_string(
      "<scene version='3.0.0'><tonemap type='reinhard'><float name='key' value='0.3'/>"
      "<float name='exposure' value='-1'/></tonemap></scene>",
      "tonemap.xml");
  ASSERT_TRUE(scene.tone_operator);
  EXPECT_EQ(scene.tone_operator->describe(), "reinhard key=0.300000 white=0.000000 burn=0.000000");
  EXPECT_EQ(scene.tone_operator->exposure(), -1);
  EXPECT_FALSE(load_scene_string("<scene version='3.0.0'/>", "plain.xml").tone_operator);
  EXPECT_THAT(test::load_error("<scene version='3.0.0'>\n<tonemap type='reinhard'/>\n<tonemap type='none'/></scene>"),
              HasSubstr("test.xml:3: a scene may have only one tonemap"));
}

TEST(SceneLoader, TonemapElementAsksForGlare) {
  const auto scene = load_scene_string(
      "<scene version='3.0.0'><tonemap type='filmic'><string name='glare' value='clipped'/></tonemap></scene>",
      "glare.xml");
  EXPECT_EQ(scene.tone_operator->glare(), GlareMode::Clipped);
  EXPECT_EQ(scene.tone_operator->describe(), "filmic bias=2.000000 white=11.200000");
  EXPECT_EQ(load_scene_string("<scene version='3.0.0'><tonemap type='none'/></scene>", "x.xml").tone_operator->glare(),
            GlareMode::None);
  EXPECT_THAT(test::load_error("<scene version='3.0.0'>\n<tonemap type='none'>\n<string name='glare' value='bloom'/>"
                               "</tonemap></scene>"),
              HasSubstr("test.xml:3: parameter 'glare' of tonemap 'none': must be none, whole or clipped"));
}

TEST(SceneLoader, DefaultsGiveAPerspectiveCameraAndPathTracer) {
  const auto scene = load_scene_string("<scene version='3.0.0'/>", "empty.xml");
  EXPECT_EQ(scene->sensor().film()->width(), 768);
  EXPECT_THAT(scene.integrator->describe(), StartsWith("path max_depth=-1"));
}

TEST(SceneLoader, ZeroPointSixSceneIsUpgraded) {
  const auto scene = load_scene_string(
      "<scene version='0.6.0'><integrator type='path'><integer name='maxDepth' value='3'/></integrator>"
      "<shape type='sphere'><transform name='toWorld'><translate x='1'/></transform></shape></scene>",
      "old.xml");
  EXPECT_THAT(scene.integrator->describe(), StartsWith("path max_depth=3"));
}

// What 0.x names that the plugin decides: renamed (diffuse's
// diffuseReflectance, sppm's photonCount and initialRadius, a bitmap's
// uscale/voffset as to_uv, a conductor's extEta honoured), or dropped with a
// line saying so.
TEST(SceneLoader, ZeroPointSixParametersAreUpgradedOrSaidToBeIgnored) {
  const auto checker = std::filesystem::temp_directory_path() / "caustica_upgrade.ppm";
  {
    // 2x1: black then white, read raw.
    std::ofstream out(checker, std::ios::binary);
    out << "P6\n2 1\n255\n";
    out.put(0).put(0).put(0).put(char(255)).put(char(255)).put(char(255));
  }
  const auto scene = load_scene_string(
      "<scene version='0.6.0'>\n<integrator type='sppm'><integer name='photonCount' value='5000'/>"
      "<float name='initialRadius' value='0.25'/>\n<integer name='maxPasses' value='4'/></integrator>\n"
      "<shape type='sphere'><bsdf type='diffuse'><spectrum name='diffuseReflectance' value='0.3'/></bsdf>"
      "<emitter type='area'>\n<float name='samplingWeight' value='2'/><rgb name='radiance' value='1'/>"
      "</emitter></shape>\n<shape type='sphere'><bsdf type='conductor'><rgb name='eta' value='2'/>"
      "<rgb name='k' value='0'/><float name='extEta' value='2'/></bsdf></shape>\n"
      "<shape type='sphere'><bsdf type='diffuse'><texture type='bitmap' name='reflectance'>"
      "<string name='filename' value='" +
          checker.string() +
          "'/><boolean name='raw' value='true'/><string name='filterType' value='nearest'/>"
          "<float name='uscale' value='0.5'/><float name='voffset' value='0.25'/></texture></bsdf></shape></scene>",
      "old.xml");
  EXPECT_THAT(scene.integrator->describe(), testing::HasSubstr("photons=5000 radius=0.250000"));
  EXPECT_THAT(scene.warnings,
              testing::ElementsAre(
                  "old.xml:3: parameter 'max_passes' of integrator 'sppm' (Mitsuba 0.x) is ignored: sppm runs one "
                  "iteration per sample per pixel",
                  "old.xml:5: parameter 'sampling_weight' of emitter 'area' (Mitsuba 0.x) is ignored: emitters are "
                  "chosen in proportion to their power"));
  const BsdfContext ctx;
  EXPECT_FLOAT_EQ(scene->shapes()[0]->bsdf()->albedo(ctx, {0, 0, 1}).g, 0.3f);
  // eta 2 relative to 2 is index-matched: nothing reflects.
  EXPECT_NEAR(scene->shapes()[1]->bsdf()->albedo(ctx, {0, 0, 1}).r, 0, 1e-6);
  // u 0.75 scaled by 0.5 reads the black texel; unscaled it would read the white one.
  BsdfContext at;
  at.uv = {0.75f, 0.5f};
  EXPECT_EQ(scene->shapes()[2]->bsdf()->albedo(at, {0, 0, 1}).r, 0);
  at.uv = {1.5f, 0.5f};
  EXPECT_GT(scene->shapes()[2]->bsdf()->albedo(at, {0, 0, 1}).r, 0.9f);
}

// What real 0.x files hold (found by the compatibility corpus,
// scenes/compat/refused): <srgb> colours, hex ones included, decoded from
// sRGB; a bitmap's gamma 1 as raw and its ewa/trilinear filters as bilinear;
// a checkerboard's uscale; a sampler's dimension; volpath_simple.
TEST(SceneLoader, ZeroPointSixColoursTexturesAndSamplersAreUpgraded) {
  const auto checker = std::filesystem::temp_directory_path() / "caustica_upgrade_gamma.ppm";
  {
    // 1x1 of value 128: 128/255 raw, 0.2158605 decoded.
    std::ofstream out(checker, std::ios::binary);
    out << "P6\n1 1\n255\n";
    out.put(char(128)).put(char(128)).put(char(128));
  }
  const auto scene = load_scene_string(
      "<scene version='0.6.0'>\n<integrator type='volpath_simple'/>\n<sensor type='perspective'>"
      "<sampler type='ldsampler'><integer name='dimension' value='4'/></sampler></sensor>\n"
      "<shape type='sphere'><bsdf type='diffuse'><srgb name='reflectance' value='#3366aa'/></bsdf></shape>\n"
      "<shape type='sphere'><bsdf type='diffuse'><srgb name='reflectance' value='0.5, 0.04, 1'/></bsdf></shape>\n"
      "<shape type='sphere'><bsdf type='diffuse'><texture type='bitmap' name='reflectance'><string "
      "name='filename' value='" +
          checker.string() +
          "'/><float name='gamma' value='1'/>\n<string name='filterType' value='ewa'/></texture></bsdf></shape>\n"
          "<shape type='sphere'><bsdf type='diffuse'><texture type='checkerboard' name='reflectance'>"
          "<float name='uscale' value='4'/></texture></bsdf></shape></scene>",
      "old.xml");
  EXPECT_THAT(scene.integrator->describe(), StartsWith("volpath"));
  EXPECT_THAT(scene.warnings,
              testing::ElementsAre(
                  "old.xml:2: integrator 'volpath_simple' (Mitsuba 0.x) is rendered by volpath, which samples the "
                  "same paths and also weighs them by MIS",
                  "old.xml:3: parameter 'dimension' of sampler 'ldsampler' (Mitsuba 0.x) is ignored: caustica's "
                  "samplers draw as many dimensions as each path needs",
                  "old.xml:7: filter_type 'ewa' (Mitsuba 0.x) is read as bilinear: caustica keeps no MIP maps"));
  // sRGB decoding, IEC 61966-2-1: ((c + 0.055) / 1.055)^2.4 above 0.04045, c / 12.92 below.
  const auto decoded = [](double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); };
  const BsdfContext ctx;
  const Color hex = scene->shapes()[0]->bsdf()->albedo(ctx, {0, 0, 1});
  EXPECT_NEAR(hex.r, decoded(0x33 / 255.0), 1e-6);
  EXPECT_NEAR(hex.g, decoded(0x66 / 255.0), 1e-6);
  EXPECT_NEAR(hex.b, decoded(0xaa / 255.0), 1e-6);
  const Color numbers = scene->shapes()[1]->bsdf()->albedo(ctx, {0, 0, 1});
  EXPECT_NEAR(numbers.r, 0.21404114, 1e-6);
  EXPECT_NEAR(numbers.g, 0.04 / 12.92, 1e-7);
  EXPECT_NEAR(numbers.b, 1, 1e-6);
  EXPECT_NEAR(scene->shapes()[2]->bsdf()->albedo(ctx, {0, 0, 1}).g, 128 / 255.0, 1e-6);
  // A checkerboard has two checks a unit of u; scaled by 4, u 0.15 (0.6)
  // and u 0.05 (0.2) fall in different checks, unscaled in the same one.
  BsdfContext at;
  at.uv = {0.15f, 0.1f};
  const Color check = scene->shapes()[3]->bsdf()->albedo(at, {0, 0, 1});
  at.uv = {0.05f, 0.1f};
  EXPECT_NE(check, scene->shapes()[3]->bsdf()->albedo(at, {0, 0, 1}));
}

// 0.6's bitmap parameters: wrapModeU and wrapModeV wrap each axis apart,
// channel reads one channel, maxAnisotropy and cache are dropped with a
// note each.
TEST(SceneLoader, ZeroPointSixBitmapParametersAreRead) {
  const auto image = std::filesystem::temp_directory_path() / "caustica_upgrade_wrap.pfm";
  {
    // 2 x 1, one channel: 0.25 left, 0.75 right (PFM stores rows bottom up).
    std::ofstream out(image, std::ios::binary);
    out << "Pf\n2 1\n-1.0\n";
    const float px[2] = {0.25f, 0.75f};
    out.write(reinterpret_cast<const char*>(px), sizeof px);
  }
  const auto scene = load_scene_string(
      "<scene version='0.6.0'>\n<shape type='sphere'><bsdf type='diffuse'><texture type='bitmap' "
      "name='reflectance'><string name='filename' value='" +
          image.string() +
          "'/><string name='wrapModeU' value='clamp'/><string name='wrapModeV' value='zero'/>\n"
          "<float name='maxAnisotropy' value='16'/>\n<boolean name='cache' value='false'/>"
          "<string name='filterType' value='nearest'/><string name='channel' value='y'/></texture></bsdf></shape>"
          "</scene>",
      "old.xml");
  EXPECT_THAT(scene.warnings,
              testing::ElementsAre("old.xml:3: parameter 'max_anisotropy' of texture 'bitmap' (Mitsuba 0.x) is "
                                   "ignored: caustica keeps no MIP maps to filter anisotropically",
                                   "old.xml:4: parameter 'cache' of texture 'bitmap' (Mitsuba 0.x) is ignored: "
                                   "caustica reads the image itself and keeps no MIP-map cache file"));
  const auto albedo = [&](float u, float v) {
    BsdfContext at;
    at.uv = {u, v};
    return scene->shapes()[0]->bsdf()->albedo(at, {0, 0, 1}).r;
  };
  EXPECT_NEAR(albedo(1.6f, 0.5f), 0.75f, 1e-6);  // clamped along u
  EXPECT_NEAR(albedo(-0.6f, 0.5f), 0.25f, 1e-6);
  EXPECT_EQ(albedo(0.25f, 1.5f), 0.0f);  // zero along v
}

struct BadInput {
  const char* what;
  std::string xml;
  std::string message;
};

class SceneLoaderError : public testing::TestWithParam<BadInput> {};

TEST_P(SceneLoaderError, NamesFileLineAndProblem) {
  EXPECT_THAT(test::load_error(GetParam().xml, "bad.xml"), HasSubstr(GetParam().message)) << GetParam().what;
}

INSTANTIATE_TEST_SUITE_P(
    BadInputs, SceneLoaderError,
    testing::Values(
        BadInput{"malformed XML", "<scene version='3.0.0'>\n<shape type='sphere'>\n</scene>",
                 "bad.xml:3: malformed XML"},
        BadInput{
            "unknown plugin", "<scene version='3.0.0'>\n<bsdf type='velvet'/></scene>",
            "bad.xml:2: unknown bsdf type 'velvet' (available: blendbsdf, bumpmap, conductor, dielectric, diffuse"},
        BadInput{"unknown parameter",
                 "<scene version='3.0.0'>\n<shape type='sphere'>\n<float name='radius' value='1'/>\n"
                 "<float name='radios' value='1'/></shape></scene>",
                 "bad.xml:4: unknown parameter 'radios' for shape 'sphere' (accepted: center, radius, to_world, "
                 "flip_normals, interior, exterior, silhouette_sampling_weight)"},
        BadInput{"wrong value type",
                 "<scene version='3.0.0'>\n<sensor type='perspective'>\n<string name='fov' value='wide'/>"
                 "</sensor></scene>",
                 "bad.xml:3: parameter 'fov' of sensor 'perspective' must be float, not string"},
        BadInput{"unparsable number",
                 "<scene version='3.0.0'>\n<shape type='sphere'><float name='radius' value='1m'/></shape></scene>",
                 "cannot parse '1m' as float"},
        BadInput{"missing mesh file",
                 "<scene version='3.0.0'>\n<shape type='obj'>\n<string name='filename' value='nowhere.obj'/>"
                 "</shape></scene>",
                 "bad.xml:3: parameter 'filename' of shape 'obj': mesh file 'nowhere.obj' not found"},
        BadInput{"undefined $name", "<scene version='3.0.0'>\n\n<integer name='x' value='$spp'/></scene>",
                 "bad.xml:3: undefined parameter '$spp'"},
        BadInput{"dangling ref", "<scene version='3.0.0'>\n<shape type='cube'>\n<ref id='gold'/></shape></scene>",
                 "bad.xml:3: reference to undefined id 'gold'"},
        BadInput{"duplicate id",
                 "<scene version='3.0.0'>\n<bsdf type='diffuse' id='a'/>\n<bsdf type='diffuse' id='a'/></scene>",
                 "bad.xml:3: id 'a' is already used at bad.xml:2"},
        BadInput{"required parameter", "<scene version='3.0.0'>\n<shape type='obj'/></scene>",
                 "bad.xml:2: shape 'obj' requires parameter 'filename'"},
        BadInput{"misplaced child",
                 "<scene version='3.0.0'>\n<bsdf type='diffuse'>\n<emitter type='area'><rgb name='radiance' value='1'/>"
                 "</emitter></bsdf></scene>",
                 "bad.xml:3: bsdf 'diffuse' does not take a nested <emitter>"},
        BadInput{"texture under a wrong name",
                 "<scene version='3.0.0'>\n<bsdf type='diffuse'>\n<texture type='checkerboard' "
                 "name='diffuse_reflectance'/></bsdf></scene>",
                 "bad.xml:3: bsdf 'diffuse' has no parameter 'diffuse_reflectance' that takes a <texture> (those "
                 "that do: reflectance)"},
        BadInput{"texture without a name",
                 "<scene version='3.0.0'>\n<bsdf type='diffuse'>\n<texture type='checkerboard'/></bsdf></scene>",
                 "bad.xml:3: bsdf 'diffuse' takes a nested <texture> only as a parameter: name it (name=\"...\"): "
                 "reflectance"},
        BadInput{"crop window beyond the film",
                 "<scene version='3.0.0'>\n<sensor type='perspective'><film type='hdrfilm'>"
                 "<integer name='width' value='16'/><integer name='crop_offset_x' value='10'/>\n"
                 "<integer name='crop_width' value='7'/></film></sensor></scene>",
                 "bad.xml:3: parameter 'crop_width' of film 'hdrfilm': must be between 1 and 6"},
        BadInput{"unknown pixel format",
                 "<scene version='3.0.0'>\n<sensor type='perspective'><film type='hdrfilm'>\n"
                 "<string name='pixel_format' value='spectrum'/></film></sensor></scene>",
                 "bad.xml:3: parameter 'pixel_format' of film 'hdrfilm': must be rgb, rgba, luminance, "
                 "luminance_alpha, xyz or xyza, not 'spectrum'"},
        BadInput{"unknown file format",
                 "<scene version='3.0.0'>\n<sensor type='perspective'><film type='hdrfilm'>\n"
                 "<string name='file_format' value='png'/></film></sensor></scene>",
                 "bad.xml:3: parameter 'file_format' of film 'hdrfilm': must be openexr, rgbe or pfm, not 'png'"},
        BadInput{"spectrum with falling wavelengths",
                 "<scene version='3.0.0'>\n<bsdf type='diffuse'>\n<spectrum name='reflectance' "
                 "value='400:0.5, 300:1'/></bsdf></scene>",
                 "bad.xml:3: <spectrum>: wavelengths must increase, but 300.000000 nm follows 400.000000 nm"},
        BadInput{"negative spectrum value",
                 "<scene version='3.0.0'>\n<bsdf type='diffuse'>\n<spectrum name='reflectance' "
                 "value='400:0.5, 500:-0.25, 600:0.5'/></bsdf></scene>",
                 "bad.xml:3: <spectrum>: value -0.250000 at 500.000000 nm is negative"},
        BadInput{"spectrum of one wavelength",
                 "<scene version='3.0.0'>\n<bsdf type='diffuse'>\n<spectrum name='reflectance' "
                 "value='500:0.5'/></bsdf></scene>",
                 "bad.xml:3: <spectrum>: the spectrum holds one wavelength only (500.000000 nm)"},
        BadInput{"black body of negative scale",
                 "<scene version='3.0.0'>\n<emitter type='constant'>\n<blackbody name='radiance' temperature='3000' "
                 "multiplier='-1'/></emitter></scene>",
                 "bad.xml:3: a black body's scale must not be negative"},
        BadInput{"black body of negative scale, Mitsuba 3's form",
                 "<scene version='3.0.0'>\n<emitter type='constant'>\n<spectrum name='radiance' type='blackbody'>"
                 "<float name='temperature' value='3000'/><float name='scale' value='-1'/></spectrum>"
                 "</emitter></scene>",
                 "bad.xml:3: a black body's scale must not be negative"},
        BadInput{"unknown spectrum type",
                 "<scene version='3.0.0'>\n<bsdf type='diffuse'>\n<spectrum name='reflectance' type='d50'/>"
                 "</bsdf></scene>",
                 "bad.xml:3: <spectrum type='d50'> is not known (known: blackbody)"},
        BadInput{"black body without a temperature",
                 "<scene version='3.0.0'>\n<emitter type='constant'>\n<blackbody name='radiance'/>"
                 "</emitter></scene>",
                 "bad.xml:3: <blackbody> needs a 'temperature' attribute"},
        BadInput{"missing spectrum file",
                 "<scene version='3.0.0'>\n<bsdf type='diffuse'>\n<spectrum name='reflectance' "
                 "filename='nowhere.spd'/></bsdf></scene>",
                 "bad.xml:3: <spectrum>: spectrum file 'nowhere.spd' not found"},
        BadInput{"directory as a spectrum file",
                 "<scene version='3.0.0'>\n<bsdf type='diffuse'>\n<spectrum name='reflectance' "
                 "filename='/tmp'/></bsdf></scene>",
                 "bad.xml:3: <spectrum>: spectrum file '/tmp' is a directory"},
        BadInput{"device as a spectrum file",
                 "<scene version='3.0.0'>\n<bsdf type='diffuse'>\n<spectrum name='reflectance' "
                 "filename='/dev/zero'/></bsdf></scene>",
                 "bad.xml:3: <spectrum>: spectrum file '/dev/zero' is not a regular file (a device or a pipe)"},
        BadInput{"directory as a mesh",
                 "<scene version='3.0.0'>\n<shape type='ply'>\n<string name='filename' value='/tmp'/></shape></scene>",
                 "bad.xml:3: parameter 'filename' of shape 'ply': mesh file '/tmp' is a directory"},
        BadInput{"device as an image",
                 "<scene version='3.0.0'>\n<texture type='bitmap'>\n<string name='filename' value='/dev/zero'/>"
                 "</texture></scene>",
                 "bad.xml:3: parameter 'filename' of texture 'bitmap': image file '/dev/zero' is not a regular file "
                 "(a device or a pipe)"},
        BadInput{"directory as a volume",
                 "<scene version='3.0.0'>\n<volume type='gridvolume'>\n<string name='filename' value='/tmp'/>"
                 "</volume></scene>",
                 "bad.xml:3: parameter 'filename' of volume 'gridvolume': volume file '/tmp' is a directory"},
        BadInput{"missing aperture",
                 "<scene version='3.0.0'>\n<sensor type='thinlens'>\n<float name='focus_distance' value='2'/>"
                 "</sensor></scene>",
                 "bad.xml:2: sensor 'thinlens' requires parameter 'aperture_radius'"},
        BadInput{"top-level area emitter",
                 "<scene version='3.0.0'>\n<emitter type='area'><rgb name='radiance' value='1'/></emitter></scene>",
                 "bad.xml:2: an area emitter must be nested in a shape or referenced by one (<ref id=\"...\"/>)"},
        BadInput{"point light in a shape",
                 "<scene version='3.0.0'>\n<shape type='cube'>\n<emitter type='point'/></shape></scene>",
                 "bad.xml:2: only an area emitter can be nested in a shape"},
        BadInput{"bad enumeration",
                 "<scene version='3.0.0'>\n<sensor type='perspective'>\n"
                 "<string name='fov_axis' value='z'/></sensor></scene>",
                 "bad.xml:3: parameter 'fov_axis' of sensor 'perspective': must be x, y, diagonal, smaller or larger"},
        BadInput{"unknown element",
                 "<scene version='3.0.0'>\n<shape type='cube'>\n<colour name='a' value='1'/>"
                 "</shape></scene>",
                 "bad.xml:3: unknown element <colour>"},
        BadInput{"bad transform step",
                 "<scene version='3.0.0'>\n<shape type='cube'><transform name='to_world'>\n"
                 "<shear value='1'/></transform></shape></scene>",
                 "bad.xml:3: unknown transform step <shear>"},
        BadInput{"singular matrix",
                 "<scene version='3.0.0'>\n<shape type='cube'><transform name='to_world'>\n"
                 "<scale value='0'/></transform></shape></scene>",
                 "bad.xml:3: transform matrix is singular"},
        BadInput{"degenerate lookat",
                 "<scene version='3.0.0'>\n<sensor type='perspective'><transform name='to_world'>\n"
                 "<lookat origin='1, 1, 1' target='1, 1, 1'/></transform></sensor></scene>",
                 "bad.xml:3: lookat: origin and target coincide"},
        BadInput{"zero up vector",
                 "<scene version='3.0.0'>\n<sensor type='perspective'><transform name='to_world'>\n"
                 "<lookat origin='1, 1, 1' target='0, 0, 0' up='0, 0, 0'/></transform></sensor></scene>",
                 "bad.xml:3: lookat: 'up' is zero or parallel to the viewing direction"},
        BadInput{"short matrix",
                 "<scene version='3.0.0'>\n<shape type='cube'><transform name='to_world'>\n"
                 "<matrix value='1 0 0 0 1 0 0 0 1'/></transform></shape></scene>",
                 "bad.xml:3: <matrix> needs 16 numbers (row-major 4x4), found 9"},
        BadInput{"sheared sphere",
                 "<scene version='3.0.0'>\n<shape type='sphere'><transform name='to_world'>\n"
                 "<matrix value='1 0 0 0  0 1 0.5 0  0 0 1 0  0 0 0 1'/></transform></shape></scene>",
                 "bad.xml:2: parameter 'to_world' of shape 'sphere': a sphere's to_world may only translate"},
        BadInput{"huge film",
                 "<scene version='3.0.0'>\n<sensor type='perspective'><film type='hdrfilm'>\n"
                 "<integer name='width' value='65536'/><integer name='height' value='65536'/></film>"
                 "</sensor></scene>",
                 "width x height must be at most 67108864 pixels"},
        BadInput{"duplicate attribute",
                 "<scene version='3.0.0'>\n<shape type='sphere'>\n<float name='radius' value='1' value='2'/>"
                 "</shape></scene>",
                 "bad.xml:3: <float> has two 'value' attributes"},
        BadInput{"negative point intensity",
                 "<scene version='3.0.0'>\n<emitter type='point'>\n<rgb name='intensity' value='1, -1, 1'/>"
                 "</emitter></scene>",
                 "bad.xml:3: parameter 'intensity' of emitter 'point': must not be negative"},
        BadInput{"negative environment",
                 "<scene version='3.0.0'>\n<emitter type='constant'>\n<float name='radiance' value='-0.5'/>"
                 "</emitter></scene>",
                 "bad.xml:3: parameter 'radiance' of emitter 'constant': must not be negative"},
        BadInput{"emitter power beyond float",
                 "<scene version='3.0.0'>\n<shape type='sphere'/>\n<emitter type='point'>"
                 "<rgb name='intensity' value='1e37'/></emitter></scene>",
                 "bad.xml:3: the emitter's power (1.26e+38, 1.26e+38, 1.26e+38 W) overflows single precision"},
        BadInput{"negative reflectance",
                 "<scene version='3.0.0'>\n<bsdf type='diffuse'>\n<rgb name='reflectance' value='0.5, -0.1, 0.5'/>"
                 "</bsdf></scene>",
                 "bad.xml:3: parameter 'reflectance' of bsdf 'diffuse': must not be negative (it goes down to -0.1)"},
        BadInput{"negative check in a checkerboard reflectance",
                 "<scene version='3.0.0'>\n<bsdf type='plastic'>\n<texture type='checkerboard' "
                 "name='diffuse_reflectance'><float name='color1' value='-2'/></texture></bsdf></scene>",
                 "parameter 'diffuse_reflectance' of bsdf 'plastic': must not be negative (it goes down to -2)"},
        BadInput{"opacity above one",
                 "<scene version='3.0.0'>\n<bsdf type='mask'>\n<float name='opacity' value='1.5'/>"
                 "<bsdf type='diffuse'/></bsdf></scene>",
                 "bad.xml:3: parameter 'opacity' of bsdf 'mask': must lie in [0, 1] (it spans 1.5 to 1.5)"},
        BadInput{"scaled camera",
                 "<scene version='3.0.0'>\n<sensor type='perspective'><transform name='to_world'>\n"
                 "<scale value='2'/></transform></sensor></scene>",
                 "bad.xml:2: parameter 'to_world' of sensor 'perspective': must not scale"},
        BadInput{"huge value quoted",
                 "<scene version='3.0.0'>\n<shape type='sphere'><float name='radius' value='" +
                     std::string(10000000, '7') + "x'/></shape></scene>",
                 "bad.xml:2: cannot parse '" + std::string(60, '7') + "... (10000001 characters)' as float"},
        BadInput{"two sensors",
                 "<scene version='3.0.0'>\n<sensor type='perspective'/>\n<sensor type='perspective'/>"
                 "</scene>",
                 "bad.xml:3: a scene may have only one sensor"}),
    [](const testing::TestParamInfo<BadInput>& info) {
      std::string name;
      for (const char* c = info.param.what; *c; ++c) name += std::isalnum(static_cast<unsigned char>(*c)) ? *c : '_';
      return name;
    });

TEST(SceneLoader, UnknownIntegratorOverrideListsTheAvailableOnes) {
  try {
    make_integrator("bdpt2");
    FAIL();
  } catch (const std::exception& e) {
    EXPECT_THAT(
        e.what(),
        HasSubstr("unknown integrator 'bdpt2' (available: aov, bdpt, direct, guided_path, mlt, path, photon, ptracer"));
  }
}

TEST(SceneLoader, IntegratorSpecWithParameters) {
  const auto bdpt = make_integrator("bdpt:max_depth=3,mis=balance,strategy_layers=2");
  EXPECT_EQ(bdpt->describe(),
            "bdpt max_depth=3 rr_depth=1 rr_max_survival=0.950000 rr_threshold=0.100000 hide_emitters=false "
            "mis=balance strategy_layers=2");
  EXPECT_EQ(make_integrator("path:hide_emitters=true")->describe(),
            "path max_depth=-1 rr_depth=5 rr_max_survival=0.950000 rr_threshold=0.100000 hide_emitters=true");
}

TEST(SceneLoader, BadIntegratorSpecs) {
  const auto message = [](const std::string& spec) {
    try {
      make_integrator(spec);
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_THAT(message("bdpt:max_depth"),
              HasSubstr("--integrator bdpt:max_depth: expected name=value, got 'max_depth'"));
  EXPECT_THAT(message("bdpt:depth=3"), HasSubstr("--integrator bdpt:depth=3: "));
  EXPECT_THAT(message("bdpt:depth=3"), HasSubstr("max_depth"));
  EXPECT_THAT(message("path:max_depth=two"), HasSubstr("--integrator path:max_depth=two: "));
  EXPECT_THAT(message("bdpt:mis=cubic"), HasSubstr("must be power or balance, not 'cubic'"));
}

// A chain of references recurses like nesting: it is bounded too (b0 on
// line 2 is the first of the 64 objects built, b64 on line 66 is refused).
TEST(SceneLoader, LongChainsOfReferencesAreRefused) {
  std::string xml = "<scene version='3.0.0'>\n";
  for (int i = 0; i < 100; ++i)
    xml += "<bsdf type='twosided' id='b" + std::to_string(i) + "'><ref id='b" + std::to_string(i + 1) + "'/></bsdf>\n";
  xml += "<bsdf type='diffuse' id='b100'/>\n<shape type='sphere'><ref id='b0'/></shape></scene>";
  EXPECT_THAT(test::load_error(xml, "chain.xml"),
              HasSubstr("chain.xml:66: objects nested or referring to each other more than 64 deep"));
}

// So is a chain declared in order, each object referring to the one
// before (b0 on line 2 is one level deep, b64 on line 66 would be 65):
// built one by one, each from the last, it never recursed.
TEST(SceneLoader, LongChainsOfEarlierObjectsAreRefused) {
  std::string xml = "<scene version='3.0.0'>\n<bsdf type='diffuse' id='b0'/>\n";
  for (int i = 1; i < 100; ++i)
    xml += "<bsdf type='twosided' id='b" + std::to_string(i) + "'><ref id='b" + std::to_string(i - 1) + "'/></bsdf>\n";
  xml += "<shape type='sphere'><ref id='b99'/></shape></scene>";
  EXPECT_THAT(test::load_error(xml, "chain.xml"),
              HasSubstr("chain.xml:66: objects nested or referring to each other more than 64 deep"));
}

// A chain as deep as allowed (a shape and 63 BSDFs) renders: each twosided
// works out what it says of itself once, instead of asking its front and
// back (here one BSDF, asked twice) at every query, 2^62 times down the
// chain.
TEST(SceneLoader, ADeepChainOfTwosidedRenders) {
  std::string xml =
      "<scene version='3.0.0'><sensor type='perspective'><film type='hdrfilm'><integer name='width' value='4'/>"
      "<integer name='height' value='4'/></film><transform name='to_world'><lookat origin='0, 0, 4' target='0, 0, "
      "0' up='0, 1, 0'/></transform></sensor><emitter type='constant'/><bsdf type='diffuse' id='b0'/>";
  for (int i = 1; i < 63; ++i)
    xml += "<bsdf type='twosided' id='b" + std::to_string(i) + "'><ref id='b" + std::to_string(i - 1) + "'/></bsdf>";
  xml += "<shape type='sphere'><ref id='b62'/></shape></scene>";
  const auto scene = test::scene_from_xml(xml);
  double sum = 0;
  for (float v : test::render_scene(scene, 1).resolve()) sum += v;
  EXPECT_GT(sum, 0);
}

// A blendbsdf whose two parts are the blend before evaluates 2^n BSDFs at
// every shading point: refused once a material would evaluate more than
// 4096 (b12, on line 14, would evaluate 8191).
TEST(SceneLoader, MaterialsThatEvaluateTooManyBsdfsAreRefused) {
  std::string xml = "<scene version='3.0.0'>\n<bsdf type='diffuse' id='b0'/>\n";
  for (int i = 1; i < 20; ++i)
    xml += "<bsdf type='blendbsdf' id='b" + std::to_string(i) + "'><ref id='b" + std::to_string(i - 1) +
           "'/><ref id='b" + std::to_string(i - 1) + "'/></bsdf>\n";
  xml += "<shape type='sphere'><ref id='b19'/></shape></scene>";
  EXPECT_THAT(test::load_error(xml, "blend.xml"),
              HasSubstr("blend.xml:14: this bsdf holds, counting a referenced one each time it is used, 8.19e+03 "
                        "BSDFs and textures, all evaluated at every shading point; at most 4096 are allowed"));
}

// A stop request (Ctrl-C) is seen between the objects a scene builds, so
// loading a million instances can be interrupted; afterwards loads go on.
TEST(SceneLoader, AStopRequestInterruptsTheBuild) {
  std::string xml = "<scene version='3.0.0'><shape type='shapegroup' id='g'><shape type='sphere'/></shape>";
  for (int i = 0; i < 100; ++i)
    xml += "<shape type='instance'><ref id='g'/><transform name='to_world'><translate x='" + std::to_string(3 * i) +
           "'/></transform></shape>";
  xml += "</scene>";
  stop_request().store(true);
  EXPECT_THROW(test::scene_from_xml(xml), Interrupted);
  stop_request().store(false);
  EXPECT_EQ(test::scene_from_xml(xml)->shapes().size(), 100u);
}

// The excerpt keeps a hostile value's message short.
TEST(SceneLoader, ErrorsQuoteOnlyAnExcerptOfLongValues) {
  const std::string error =
      test::load_error("<scene version='3.0.0'><shape type='sphere'><float name='radius' value='" +
                       std::string(10000000, '7') + "x'/></shape></scene>");
  EXPECT_LT(error.size(), 300u);
}

// As Mitsuba reads them: numbers with an explicit '+', and a point light's
// position given as a <vector> (as Blender's exporter writes it).
TEST(SceneLoader, ValuesAsExportersWriteThem) {
  const auto scene = test::scene_from_xml(
      "<scene version='3.0.0'><shape type='sphere'><float name='radius' value='+0.5'/>"
      "<point name='center' value='+1, -2, +3'/></shape>"
      "<emitter type='point'><vector name='position' x='0' y='+2' z='0'/><rgb name='intensity' value='1'/>"
      "</emitter><sensor type='perspective'><film type='hdrfilm'><integer name='width' value='+8'/>"
      "</film></sensor></scene>");
  EXPECT_FLOAT_EQ(scene->shapes()[0]->area(), float(4 * M_PI * 0.25));
  EXPECT_EQ(scene->sensor().film()->width(), 8);
  const auto hit = scene->intersect({scene->render_point({1, -2, 10}), {0, 0, -1}});
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 6.5, 1e-5);
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><shape type='sphere'><float name='radius' value='++1'/>"
                               "</shape></scene>"),
              HasSubstr("cannot parse '++1' as float"));
}

// Files are found as Mitsuba finds them too: along <path> folders (for
// includes and for everything named), and beside the main scene when an
// included fragment names them, as well as beside the naming file.
TEST(SceneLoader, FilesAreFoundAlongPathsAndBesideTheMainScene) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "caustica_paths";
  fs::remove_all(dir);
  fs::create_directories(dir / "assets");
  fs::create_directories(dir / "parts");
  fs::create_directories(dir / "meshes");
  const std::string triangle =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  std::ofstream(dir / "assets" / "in_assets.ply") << triangle;
  std::ofstream(dir / "meshes" / "beside_main.ply") << triangle;
  std::ofstream(dir / "assets" / "light.xml")
      << "<scene version='3.0.0'><emitter type='point'><rgb name='intensity' value='1'/></emitter></scene>";
  std::ofstream(dir / "parts" / "fragment.xml")
      << "<scene version='3.0.0'><shape type='ply'><string name='filename' value='meshes/beside_main.ply'/>"
         "</shape></scene>";
  std::ofstream(dir / "main.xml")
      << "<scene version='3.0.0'><path value='assets'/><include filename='light.xml'/>"
         "<include filename='parts/fragment.xml'/>"
         "<shape type='ply'><string name='filename' value='in_assets.ply'/></shape></scene>";
  const LoadedScene scene = load_scene(dir / "main.xml");
  EXPECT_EQ(scene->shapes().size(), 2u);
  EXPECT_EQ(scene->emitters().size(), 1u);

  EXPECT_THAT(test::load_error("<scene version='3.0.0'>\n<path value='nowhere'/></scene>", (dir / "bad.xml").string()),
              HasSubstr("bad.xml:2: <path> '" + (dir / "nowhere").string() + "' is not a folder"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'>\n<shape type='cube'>\n<path value='assets'/></shape></scene>"),
              HasSubstr("test.xml:3: <path> must be a direct child of <scene>"));
}

TEST(SceneLoader, MirroredCameraIsAccepted) {
  EXPECT_NO_THROW(
      test::scene_from_xml("<scene version='3.0.0'><sensor type='perspective'><transform "
                           "name='to_world'><scale x='-1'/></transform></sensor></scene>"));
}

// Accepted, as Mitsuba accepts them, but said: a reflectance above 1 and a
// -D nothing uses.
TEST(SceneLoader, WarningsNameTheFileAndLine) {
  const LoadedScene scene = load_scene_string(
      "<scene version='3.0.0'>\n<default name='res' value='8'/>\n<shape type='sphere'>\n<bsdf type='diffuse'>\n"
      "<rgb name='reflectance' value='0.5, 5, 0.5'/></bsdf></shape></scene>",
      "warm.xml", {{"res", "16"}, {"spp", "4"}});
  EXPECT_THAT(scene.warnings,
              testing::ElementsAre("warm.xml:5: parameter 'reflectance' of bsdf 'diffuse': goes up to 5: a surface "
                                   "that reflects more light than it receives gains energy",
                                   "warm.xml: -D res is not used by the scene (no $res in it)",
                                   "warm.xml: -D spp is not used by the scene (no $spp in it)"));
  const LoadedScene used = load_scene_string(
      "<scene version='3.0.0'>\n<default name='res' value='8'/>\n<sensor type='perspective'><film type='hdrfilm'>"
      "<integer name='width' value='$res'/></film></sensor></scene>",
      "used.xml", {{"res", "16"}});
  EXPECT_TRUE(used.warnings.empty());
}

// Spectra (wavelength:value lists, .spd files, black bodies in Mitsuba 3's
// and 0.x's forms) become the RGB a flat spectrum of 2 gives: X = Y = Z = 2,
// which Rec.709's published matrix takes to 2 x (1.2047843, 0.9483008,
// 0.9088427); each scene's emitter must carry that power.
TEST(SceneLoader, SpectraBecomeRgb) {
  const auto power = [](const std::string& radiance) {
    const auto scene = test::scene_from_xml("<scene version='3.0.0'><shape type='sphere'><emitter type='area'>" +
                                            radiance + "</emitter></shape></scene>");
    return scene->emitters()[0]->power();
  };
  const Color expected = power("<rgb name='radiance' value='2.4095686, 1.8966016, 1.8176854'/>");
  const auto spd = std::filesystem::temp_directory_path() / "caustica_flat2.spd";
  std::ofstream(spd) << "360 2\n830 2\n";
  for (const std::string& radiance : {std::string("<spectrum name='radiance' value='360:2, 500:2, 830:+2'/>"),
                                      "<spectrum name='radiance' filename='" + spd.string() + "'/>"}) {
    const Color c = power(radiance);
    EXPECT_NEAR(c.r / expected.r, 1, 2e-3) << radiance;
    EXPECT_NEAR(c.g / expected.g, 1, 2e-3) << radiance;
    EXPECT_NEAR(c.b / expected.b, 1, 2e-3) << radiance;
  }
  const Color modern = power(
      "<spectrum name='radiance' type='blackbody'><float name='temperature' value='4000'/>"
      "<float name='scale' value='1e-6'/></spectrum>");
  const Color old = power("<blackbody name='radiance' temperature='4000K' multiplier='1e-6'/>");
  EXPECT_FLOAT_EQ(modern.r, old.r);
  EXPECT_GT(modern.r, modern.b);  // 4000 K is warm
}

// A spectrum file's bad values are refused naming the file and its line,
// as inline values are; a file of one line is no band.
TEST(SceneLoader, SpectrumFilesWithNegativeValuesOrOneWavelengthAreRefused) {
  const auto dir = std::filesystem::temp_directory_path();
  const auto negative = dir / "caustica_negative.spd", single = dir / "caustica_single.spd";
  std::ofstream(negative) << "# nm value\n400 0.5\n500 -0.1\n600 0.5\n";
  std::ofstream(single) << "550 0.8\n";
  const auto error = [](const std::filesystem::path& file) {
    return test::load_error("<scene version='3.0.0'>\n<bsdf type='diffuse'>\n<spectrum name='reflectance' filename='" +
                                file.string() + "'/></bsdf></scene>",
                            "spd.xml");
  };
  EXPECT_THAT(error(negative), HasSubstr("spd.xml:3: <spectrum>: " + negative.string() +
                                         ":3: value -0.100000 at 500.000000 nm is negative"));
  EXPECT_THAT(error(single), HasSubstr("spd.xml:3: <spectrum>: spectrum file '" + single.string() +
                                       "' holds one wavelength only (550.000000 nm)"));
}

// Film parameters that cannot matter to caustica are accepted, each with a
// line saying so, as are 0.x's names for them.
TEST(SceneLoader, FilmParametersWithoutEffectAreSaidToBe) {
  const LoadedScene scene = load_scene_string(
      "<scene version='3.0.0'><sensor type='perspective'><film type='hdrfilm'>\n"
      "<boolean name='banner' value='false'/>\n<boolean name='sample_border' value='true'/>\n"
      "<string name='component_format' value='uint32'/></film></sensor></scene>",
      "film.xml");
  EXPECT_THAT(scene.warnings,
              testing::UnorderedElementsAre(
                  "film.xml:2: parameter 'banner' of film 'hdrfilm': is ignored: caustica writes neither a banner nor "
                  "a log into images",
                  "film.xml:3: parameter 'sample_border' of film 'hdrfilm': has no effect: every pixel is already "
                  "filtered over the filter's whole support, at the film's borders too",
                  "film.xml:4: parameter 'component_format' of film 'hdrfilm': uint32 is written as float32: "
                  "integers would truncate the radiance"));
  const LoadedScene old = load_scene_string(
      "<scene version='0.5.0'><sensor type='perspective'><film type='hdrfilm'>"
      "<boolean name='highQualityEdges' value='false'/><boolean name='attachLog' value='true'/>"
      "<string name='fileFormat' value='openexr'/></film></sensor></scene>",
      "old.xml");
  EXPECT_THAT(old.warnings, testing::ElementsAre(HasSubstr("parameter 'attach_log' of film 'hdrfilm': is ignored")));
}

// Parameters Mitsuba 3 gives every plugin of a category, and the few of
// single plugins, that cannot change caustica's image: accepted, each with a
// line saying why it is ignored (a shutter is no longer among them: it times
// moving shapes, and without them says nothing).
TEST(SceneLoader, MitsubaParametersWithoutEffectAreSaidToBe) {
  const LoadedScene scene = load_scene_string(
      "<scene version='3.0.0'><integrator type='path'>\n<integer name='samples_per_pass' value='4'/></integrator>"
      "<sensor type='orthographic'>\n<float name='shutter_close' value='1'/>\n"
      "<float name='focus_distance' value='3'/></sensor>"
      "<shape type='sphere'>\n<float name='silhouette_sampling_weight' value='2'/>"
      "<bsdf type='diffuse'><texture type='bitmap' name='reflectance'>\n<string name='format' value='fp16'/>"
      "<string name='filename' value='" +
          std::string(CAUSTICA_SOURCE_DIR) +
          "/scenes/textures/bumps.png'/></texture></bsdf></shape>"
          "<emitter type='point'>\n<float name='sampling_weight' value='3'/></emitter></scene>",
      "ignored.xml");
  EXPECT_THAT(
      scene.warnings,
      testing::UnorderedElementsAre(
          "ignored.xml:2: parameter 'samples_per_pass' of integrator 'path': is ignored: the image does not depend "
          "on how its samples are split into passes",
          "ignored.xml:4: parameter 'focus_distance' of sensor 'orthographic': is ignored: parallel rays have no "
          "focus",
          "ignored.xml:5: parameter 'silhouette_sampling_weight' of shape 'sphere': is ignored: it weighs "
          "silhouette sampling in differentiable rendering, which caustica does not do",
          "ignored.xml:6: parameter 'format' of texture 'bitmap': is ignored: caustica keeps textures in float",
          "ignored.xml:7: parameter 'sampling_weight' of emitter 'point': is ignored: caustica chooses lights in "
          "proportion to their power; the image is the same, only its noise differs"));
}

// As Mitsuba: an area light without a radiance gives 1.
TEST(SceneLoader, AreaLightRadianceDefaultsToOne) {
  const LoadedScene scene = load_scene_string(
      "<scene version='3.0.0'><shape type='sphere'><emitter type='area'/></shape></scene>", "area.xml");
  EXPECT_FLOAT_EQ(scene->emitters().front()->power().g, 4 * kPi * kPi);  // pi L times the unit sphere's 4 pi
}

// Stored relative to the camera, a small rectangle far from it is finer
// than float's spacing there: said, not rendered wrong silently.
TEST(SceneLoader, GeometryFinerThanFloatAtItsDistanceIsReported) {
  const auto shape = [](const char* distance) {
    return std::string(
               "<scene version='3.0.0'><shape type='rectangle'><transform name='to_world'>"
               "<scale value='1e-4'/><translate x='") +
           distance + "' z='" + distance + "'/></transform></shape></scene>";
  };
  EXPECT_THAT(
      test::scene_from_xml(shape("5e3")).warnings,
      testing::ElementsAre(HasSubstr("test.xml:1: parameter 'to_world' of shape 'rectangle': 2 triangles "
                                     "collapse to lines or points once stored in float relative to the camera")));
  EXPECT_TRUE(test::scene_from_xml(shape("10")).warnings.empty());
}

// Mitsuba's default clip distances are absolute, so a scene in other units
// can lose geometry to them: said, with the depths involved.
TEST(SceneLoader, ClipPlanesCuttingTheSceneAreReported) {
  const auto sphere_at = [](const char* depth, const char* radius, const char* sensor_extra = "") {
    return test::scene_from_xml(std::string("<scene version='3.0.0'><sensor type='perspective'>") + sensor_extra +
                                "</sensor><shape type='sphere'><point name='center' x='0' y='0' z='" + depth +
                                "'/><float name='radius' value='" + radius + "'/></shape></scene>")
        .warnings;
  };
  EXPECT_THAT(sphere_at("1e-3", "1e-4"),
              testing::ElementsAre("test.xml: the whole scene lies nearer to the camera (depth at most 0.0011) than "
                                   "near_clip (0.01): nothing is seen; set near_clip on the sensor"));
  EXPECT_THAT(sphere_at("2e5", "1e3"),
              testing::ElementsAre("test.xml: the scene reaches a depth of 2.01e+05 from the camera, beyond far_clip "
                                   "(1e+04): what lies beyond is not seen; set far_clip on the sensor"));
  EXPECT_THAT(sphere_at("1.005", "1"),
              testing::ElementsAre("test.xml: the scene comes within a depth of 0.005 of the camera, nearer than "
                                   "near_clip (0.01): what lies nearer is not seen"));
  EXPECT_TRUE(sphere_at("2e5", "1e3", "<float name='far_clip' value='1e6'/>").empty());
  EXPECT_TRUE(sphere_at("1e-3", "1e-4", "<float name='near_clip' value='1e-5'/>").empty());
  EXPECT_TRUE(sphere_at("0", "1").empty());
}

// A file of a few bytes can declare a gigapixel image; it is refused before
// any pixel is allocated.
TEST(SceneLoader, TexturesDeclaringHugeSizesAreRefused) {
  const auto ppm = write_temp("huge.ppm", "P6\n60000 60000\n255\n");
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><bsdf type='diffuse'><texture type='bitmap' "
                               "name='reflectance'><string name='filename' value='" +
                               ppm.string() + "'/></texture></bsdf></scene>"),
              HasSubstr("': its size 60000x60000 exceeds the limit of 65536 pixels a side and 2^28 pixels in all"));
}

// A stop request during a mesh load ends the load as an interruption, not
// as an error in the scene.
TEST(SceneLoader, AStopDuringAMeshLoadIsAnInterruption) {
  stop_request().store(true);
  EXPECT_THROW(test::scene_from_xml("<scene version='3.0.0'><shape type='obj'><string name='filename' value='" +
                                    kCornellMeshes + "floor.obj'/></shape></scene>"),
               Interrupted);
  stop_request().store(false);
}

// A face index beyond the vertices (or negative, read as a huge unsigned
// one) would be read out of bounds; it is an error naming the file and face.
TEST(SceneLoader, PlyFaceIndicesOutOfRangeAreRefused) {
  const auto dir = std::filesystem::temp_directory_path() / "caustica_bad_ply";
  std::filesystem::create_directories(dir);
  for (const auto& [name, face, shown] :
       {std::tuple("high.ply", "3 0 1 7", "7"), std::tuple("low.ply", "3 0 -1 2", "-1")}) {
    std::ofstream(dir / name) << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                 "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                 "end_header\n0 0 0\n1 0 0\n0 1 0\n"
                              << face << "\n";
    const std::string error =
        test::load_error("<scene version='3.0.0'><shape type='ply'><string name='filename' value='" +
                         (dir / name).string() + "'/></shape></scene>");
    EXPECT_THAT(error,
                HasSubstr("test.xml:1: parameter 'filename' of shape 'ply': mesh file '" + (dir / name).string() +
                          "': line 13: face 0 refers to vertex " + shown + ", but the mesh has 3 vertices"))
        << name;
  }
}

// The same for an OBJ file: the error names the file and the face's line.
TEST(SceneLoader, ObjFaceIndicesOutOfRangeAreRefused) {
  const auto file = std::filesystem::temp_directory_path() / "caustica_bad.obj";
  std::ofstream(file) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 3 2 4\n";
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><shape type='obj'><string name='filename' value='" +
                               file.string() + "'/></shape></scene>"),
              HasSubstr("test.xml:1: parameter 'filename' of shape 'obj': mesh file '" + file.string() +
                        "': line 5: face refers to vertex 4 (counting from 1), but the file defines 3"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
