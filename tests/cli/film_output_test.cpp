// What an hdrfilm's file_format, pixel_format and crop window make the
// render command write. A sphere under a constant sky of radiance
// (0.5, 1, 2): rays that miss it see the sky exactly, so corner pixels are
// known without noise.

#include <OpenImageIO/imageio.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/support/command.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

namespace fs = std::filesystem;
using test::run_caustica;
using testing::HasSubstr;

fs::path temp_dir() {
  const auto dir = fs::temp_directory_path() / "caustica_film_output_test";
  fs::create_directories(dir);
  return dir;
}

fs::path sky_scene(const std::string& film_params, const std::string& shape = "<shape type='sphere'/>") {
  const fs::path path = temp_dir() / "sky.xml";
  std::ofstream(path) << "<scene version='3.0.0'><sensor type='perspective'><transform name='to_world'>"
                         "<lookat origin='0, 0, 5' target='0, 0, 0' up='0, 1, 0'/></transform>"
                         "<sampler type='independent'><integer name='sample_count' value='4'/></sampler>"
                         "<film type='hdrfilm'><integer name='width' value='16'/><integer name='height' value='12'/>"
                      << film_params << "</film></sensor>" << shape
                      << "<emitter type='constant'><rgb name='radiance' value='0.5, 1, 2'/></emitter></scene>";
  return path;
}

struct Read {
  int width = 0, height = 0;
  std::vector<std::string> channels;
  std::vector<float> pixels;
  float at(int x, int y, const std::string& channel) const {
    const auto c = std::find(channels.begin(), channels.end(), channel) - channels.begin();
    return pixels[(size_t(y) * width + x) * channels.size() + size_t(c)];
  }
};

Read read(const fs::path& file) {
  auto in = OIIO::ImageInput::open(file.string());
  EXPECT_TRUE(in) << file;
  if (!in) return {};
  Read r{in->spec().width, in->spec().height, in->spec().channelnames, {}};
  r.pixels.resize(size_t(r.width) * r.height * r.channels.size());
  in->read_image(0, 0, 0, int(r.channels.size()), OIIO::TypeDesc::FLOAT, r.pixels.data());
  return r;
}

const float kSky[3] = {0.5f, 1, 2};

TEST(FilmOutput, FileFormatRgbeWritesARadianceFileNamedAfterTheScene) {
  const fs::path scene = sky_scene("<string name='file_format' value='rgbe'/>");
  const fs::path out = fs::current_path() / "sky.hdr";
  fs::remove(out);
  const auto r = run_caustica("render " + scene.string() + " -q");
  ASSERT_EQ(r.status, 0) << r.output;
  const Read image = read(out);
  EXPECT_EQ(image.channels.size(), 3u);
  // RGBE keeps 8 bits of mantissa per channel.
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(image.at(0, 0, std::string(1, "RGB"[c])), kSky[c], 0.01 * kSky[c]);
  fs::remove(out);
}

TEST(FilmOutput, PfmOfLuminanceHoldsY) {
  const fs::path out = temp_dir() / "sky.pfm";
  const auto r = run_caustica("render " + sky_scene("<string name='pixel_format' value='luminance'/>").string() +
                              " -q -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const Read image = read(out);
  ASSERT_EQ(image.channels.size(), 1u);
  EXPECT_NEAR(image.pixels[0], 0.2126729 * 0.5 + 0.7151522 * 1 + 0.0721750 * 2, 1e-5);
}

// Rows in the right order: the PFM of a sphere off the centre holds the Y
// of the EXR rendered with the same seed, pixel for pixel.
TEST(FilmOutput, PfmRowsMatchTheExr) {
  const std::string scene = sky_scene(
                                "<string name='pixel_format' value='luminance'/>"
                                "<string name='component_format' value='float32'/>",
                                "<shape type='sphere'><point name='center' x='0.9' y='1.2' z='0'/></shape>")
                                .string();
  const fs::path pfm = temp_dir() / "off.pfm", exr = temp_dir() / "off.exr";
  ASSERT_EQ(run_caustica("render " + scene + " -q --seed 5 -o " + pfm.string()).status, 0);
  ASSERT_EQ(run_caustica("render " + scene + " -q --seed 5 -o " + exr.string()).status, 0);
  const Read a = read(pfm), b = read(exr);
  ASSERT_EQ(a.pixels.size(), size_t(16 * 12));
  double differences = 0, contrast = 0;
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 16; ++x) {
      differences += std::abs(a.at(x, y, "Y") - b.at(x, y, "Y"));
      contrast += std::abs(b.at(x, y, "Y") - b.at(x, 11 - y, "Y"));
    }
  EXPECT_EQ(differences, 0);
  EXPECT_GT(contrast, 1);  // a flipped PFM would differ
}

// An EXR keeps R, G, B (caustica's own tools read them) and adds X, Y, Z
// and the alpha channel A: 0 where the camera sees only sky, 1 on the sphere.
TEST(FilmOutput, XyzaAddsXyzAndAlphaToTheExr) {
  const fs::path out = temp_dir() / "xyza.exr";
  const auto r = run_caustica("render " +
                              sky_scene("<string name='pixel_format' value='xyza'/>"
                                        "<string name='component_format' value='float32'/>")
                                  .string() +
                              " -q -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const Read image = read(out);
  for (const char* name : {"R", "G", "B", "X", "Y", "Z", "A"})
    EXPECT_NE(std::find(image.channels.begin(), image.channels.end(), name), image.channels.end()) << name;
  EXPECT_NEAR(image.at(0, 0, "X"), 0.4124564 * 0.5 + 0.3575761 * 1 + 0.1804375 * 2, 1e-5);
  EXPECT_NEAR(image.at(0, 0, "Y"), 0.2126729 * 0.5 + 0.7151522 * 1 + 0.0721750 * 2, 1e-5);
  EXPECT_NEAR(image.at(0, 0, "Z"), 0.0193339 * 0.5 + 0.1191920 * 1 + 0.9503041 * 2, 1e-5);
  EXPECT_EQ(image.at(0, 0, "A"), 0);
  EXPECT_EQ(image.at(8, 6, "A"), 1);
}

TEST(FilmOutput, ACropWindowRendersOnlyItsPixels) {
  const fs::path scene = sky_scene(
      "<integer name='crop_offset_x' value='4'/><integer name='crop_offset_y' value='3'/>"
      "<integer name='crop_width' value='8'/><integer name='crop_height' value='6'/>");
  const auto info = run_caustica("info " + scene.string());
  EXPECT_THAT(info.output, HasSubstr("film: 16x12, rendering the crop window 8x6 at (4, 3)"));
  const fs::path out = temp_dir() / "crop.exr";
  const auto r = run_caustica("render " + scene.string() + " -q -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const Read image = read(out);
  EXPECT_EQ(image.width, 8);
  EXPECT_EQ(image.height, 6);
}

fs::path ldr_scene(const std::string& film_params) {
  const fs::path path = temp_dir() / "ldr.xml";
  std::ofstream(path) << "<scene version='3.0.0'><sensor type='perspective'><transform name='to_world'>"
                         "<lookat origin='0, 0, 5' target='0, 0, 0' up='0, 1, 0'/></transform>"
                         "<film type='ldrfilm'><integer name='width' value='16'/><integer name='height' value='12'/>"
                      << film_params
                      << "</film></sensor><shape type='sphere'/>"
                         "<emitter type='constant'><rgb name='radiance' value='0.5, 1, 2'/></emitter></scene>";
  return path;
}

// An ldrfilm develops its image itself: 2^exposure, then a power gamma.
// The sky (0.5, 1, 2) at -2 stops and gamma 2.2 is (0.125, 0.25, 0.5)^(1/2.2)
// = (0.3888, 0.5324, 0.7297), within the dithering's step of 8-bit.
TEST(FilmOutput, AnLdrfilmDevelopsWithItsOwnExposureAndGamma) {
  const fs::path out = temp_dir() / "ldr.exr";
  const auto r = run_caustica(
      "render " + ldr_scene("<float name='gamma' value='2.2'/><float name='exposure' value='-2'/>").string() +
      " -q -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const Read png = read(temp_dir() / "ldr.png");
  ASSERT_EQ(png.channels.size(), 3u);
  const double expected[3] = {0.3888, 0.5324, 0.7297};
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(png.at(0, 0, std::string(1, "RGB"[c])), expected[c], 1.5 / 255) << c;
  auto exr = OIIO::ImageInput::open(out.string());
  ASSERT_TRUE(exr);
  EXPECT_EQ(exr->spec().get_string_attribute("caustica:develop"), "none exposure=-2.000000 gamma=2.200000");
}

TEST(FilmOutput, AnLdrfilmCanToneMapByReinhardAndWriteJpeg) {
  const fs::path out = temp_dir() / "reinhard.exr";
  fs::remove(temp_dir() / "reinhard.jpg");
  const auto r = run_caustica("render " +
                              ldr_scene("<string name='tonemap_method' value='reinhard'/>"
                                        "<float name='key' value='0.3'/><float name='burn' value='0.5'/>"
                                        "<string name='file_format' value='jpeg'/>")
                                  .string() +
                              " -q -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(fs::exists(temp_dir() / "reinhard.jpg"));
  auto exr = OIIO::ImageInput::open(out.string());
  ASSERT_TRUE(exr);
  EXPECT_EQ(exr->spec().get_string_attribute("caustica:develop"),
            "reinhard key=0.300000 white=0.000000 burn=0.500000 exposure=0.000000 display=sRGB view=Standard");
}

TEST(FilmOutput, OutputsThatCannotHoldTheRenderAreRefused) {
  const std::string scene = sky_scene("").string();
  EXPECT_THAT(run_caustica("render " + scene + " -o out.png").output,
              HasSubstr("output must end in .exr, .hdr or .pfm: out.png"));
  EXPECT_THAT(run_caustica("render " + scene + " --raw-sums -o out.hdr").output,
              HasSubstr("--raw-sums needs an .exr output, not out.hdr"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
