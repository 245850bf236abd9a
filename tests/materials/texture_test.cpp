#include "core/texture/texture.h"

#include <OpenImageIO/imageio.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "core/math/constants.h"
#include "core/registry/properties.h"
#include "tests/support/bsdf_checks.h"
#include "tests/support/scratch_dir.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

namespace fs = std::filesystem;

// A folder of images written for the tests in this file.
fs::path image_dir() {
  static const fs::path dir = [] {
    const fs::path d = test::scratch_dir() / "texture_test";
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

// Writes an image, top row first, with OpenImageIO in the given storage type.
fs::path write_image(const std::string& name, int width, int height, int channels, const std::vector<float>& pixels,
                     OIIO::TypeDesc format) {
  const fs::path path = image_dir() / name;
  auto out = OIIO::ImageOutput::create(path.string());
  EXPECT_TRUE(out) << OIIO::geterror();
  const OIIO::ImageSpec spec(width, height, channels, format);
  EXPECT_TRUE(out->open(path.string(), spec)) << out->geterror();
  EXPECT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data())) << out->geterror();
  out->close();
  return path;
}

// 8-bit values v / 255 as floats, so that OpenImageIO stores exactly v.
std::vector<float> bytes(const std::vector<int>& values) {
  std::vector<float> out;
  for (int v : values) out.push_back(float(v) / 255.0f);
  return out;
}

double srgb_eotf(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }

// A texture seen through a white diffuse BSDF: reflectance = pi f.
class TextureProbe {
 public:
  explicit TextureProbe(const std::string& texture_xml)
      : bsdf_(test::make_bsdf("<bsdf type='diffuse'>" + texture_xml + "</bsdf>")) {}
  Color operator()(float u, float v) const {
    const BsdfContext ctx{TransportMode::Radiance, {u, v}};
    return bsdf_->eval(ctx, Vec3(0, 0, 1), Vec3(0, 0, 1)) * kPi;
  }
  Color albedo() const { return bsdf_->albedo({}, Vec3(0, 0, 1)); }

 private:
  std::shared_ptr<Bsdf> bsdf_;
};

std::string bitmap_xml(const fs::path& file, const std::string& extra = "") {
  return "<texture type='bitmap' name='reflectance'><string name='filename' value='" + file.string() + "'/>" + extra +
         "</texture>";
}

std::string option(const std::string& name, const std::string& value) {
  return "<string name='" + name + "' value='" + value + "'/>";
}

void expect_color_near(Color a, Color b, float tol, const std::string& what = "") {
  EXPECT_NEAR(a.r, b.r, tol) << what;
  EXPECT_NEAR(a.g, b.g, tol) << what;
  EXPECT_NEAR(a.b, b.b, tol) << what;
}

TEST(BitmapTexture, Decodes8BitSrgbWithTheIecFormula) {
  const std::vector<int> v = {0, 10, 11, 64, 128, 200, 254, 255, 1, 33, 99, 180};
  const auto file = write_image("srgb.png", 4, 1, 3, bytes(v), OIIO::TypeDesc::UINT8);
  const TextureProbe tex(bitmap_xml(file, option("filter_type", "nearest")));
  for (int i = 0; i < 4; ++i) {
    const Color c = tex((i + 0.5f) / 4, 0.5f);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(c[k], srgb_eotf(v[3 * i + k] / 255.0), 1e-6) << "pixel " << i << " channel " << k;
  }
  // raw: the stored values, unchanged.
  const TextureProbe raw(bitmap_xml(file, option("filter_type", "nearest") + "<boolean name='raw' value='true'/>"));
  EXPECT_NEAR(raw(0.375f, 0.5f).r, 64 / 255.0f, 1e-6f);
  EXPECT_NEAR(raw(0.375f, 0.5f).g, 128 / 255.0f, 1e-6f);
}

TEST(BitmapTexture, FloatImagesAreUsedAsStored) {
  const std::vector<float> px = {3.75f, 0.001f, 0.5f, 12.0f, 0.25f, 0.0f};
  const auto file = write_image("linear.exr", 2, 1, 3, px, OIIO::TypeDesc::FLOAT);
  const TextureProbe tex(bitmap_xml(file, option("filter_type", "nearest")));
  expect_color_near(tex(0.25f, 0.5f), Color(3.75f, 0.001f, 0.5f), 1e-5f);
  expect_color_near(tex(0.75f, 0.5f), Color(12.0f, 0.25f, 0.0f), 1e-5f);
  expect_color_near(tex.albedo(), Color(3.75f, 0.001f, 0.5f), 1e-5f);  // albedo at uv (0, 0): top-left
}

TEST(BitmapTexture, GreyAndRgbaImages) {
  const auto grey = write_image("grey.png", 1, 1, 1, bytes({128}), OIIO::TypeDesc::UINT8);
  const Color g = TextureProbe(bitmap_xml(grey))(0.3f, 0.6f);
  EXPECT_NEAR(g.r, srgb_eotf(128 / 255.0), 1e-6);
  EXPECT_EQ(g.r, g.g);
  EXPECT_EQ(g.r, g.b);
  const auto rgba = write_image("rgba.exr", 1, 1, 4, {0.1f, 0.2f, 0.3f, 0.0f}, OIIO::TypeDesc::FLOAT);
  expect_color_near(TextureProbe(bitmap_xml(rgba))(0.5f, 0.5f), Color(0.1f, 0.2f, 0.3f), 1e-6f);
}

// 2 x 2, top row (a, b), bottom row (c, d).
fs::path quad() { return write_image("quad.exr", 2, 2, 1, {1.0f, 2.0f, 4.0f, 8.0f}, OIIO::TypeDesc::FLOAT); }

TEST(BitmapTexture, BilinearInterpolatesBetweenPixelCentres) {
  const TextureProbe tex(bitmap_xml(quad(), option("wrap_mode", "clamp")));
  EXPECT_NEAR(tex(0.25f, 0.25f).r, 1.0f, 1e-6f);  // a pixel centre
  EXPECT_NEAR(tex(0.75f, 0.75f).r, 8.0f, 1e-6f);
  EXPECT_NEAR(tex(0.5f, 0.5f).r, (1 + 2 + 4 + 8) / 4.0f, 1e-5f);
  EXPECT_NEAR(tex(0.375f, 0.25f).r, 0.75f * 1 + 0.25f * 2, 1e-5f);
  EXPECT_NEAR(tex(0.25f, 0.625f).r, 0.25f * 1 + 0.75f * 4, 1e-5f);
  // Repeat blends the border with the opposite side.
  const TextureProbe repeat(bitmap_xml(quad()));
  EXPECT_NEAR(repeat(0.0f, 0.25f).r, 0.5f * 1 + 0.5f * 2, 1e-5f);
}

TEST(BitmapTexture, NearestPicksTheContainingPixel) {
  const TextureProbe tex(bitmap_xml(quad(), option("filter_type", "nearest")));
  EXPECT_NEAR(tex(0.01f, 0.01f).r, 1.0f, 1e-5f);
  EXPECT_NEAR(tex(0.49f, 0.2f).r, 1.0f, 1e-5f);
  EXPECT_NEAR(tex(0.51f, 0.2f).r, 2.0f, 1e-5f);
  EXPECT_NEAR(tex(0.2f, 0.51f).r, 4.0f, 1e-5f);
  EXPECT_NEAR(tex(0.99f, 0.99f).r, 8.0f, 1e-5f);
}

TEST(BitmapTexture, VZeroIsTheTopRow) {
  // As in Mitsuba 3 (whose OBJ loader flips v by default for this reason).
  const auto file = write_image("column.exr", 1, 2, 1, {5.0f, 7.0f}, OIIO::TypeDesc::FLOAT);
  const TextureProbe tex(bitmap_xml(file, option("filter_type", "nearest")));
  EXPECT_NEAR(tex(0.5f, 0.1f).r, 5.0f, 1e-5f);  // top
  EXPECT_NEAR(tex(0.5f, 0.9f).r, 7.0f, 1e-5f);  // bottom
}

TEST(BitmapTexture, WrapModes) {
  const auto file = write_image("row.exr", 4, 1, 1, {0.0f, 1.0f, 2.0f, 3.0f}, OIIO::TypeDesc::FLOAT);
  struct Case {
    float u;
    float repeat, mirror, clamp;
  };
  const Case cases[] = {
      {0.6f, 2, 2, 2},  {1.1f, 0, 3, 3},  {1.3f, 1, 2, 3},  {2.1f, 0, 0, 3}, {-0.1f, 3, 0, 0},
      {-0.3f, 2, 1, 0}, {-1.1f, 3, 3, 0}, {-1.9f, 0, 0, 0}, {5.7f, 2, 1, 3},
  };
  for (const char* mode : {"repeat", "mirror", "clamp"}) {
    const TextureProbe tex(bitmap_xml(file, option("filter_type", "nearest") + option("wrap_mode", mode)));
    for (const Case& c : cases) {
      const float expected = std::string(mode) == "repeat"   ? c.repeat
                             : std::string(mode) == "mirror" ? c.mirror
                                                             : c.clamp;
      EXPECT_NEAR(tex(c.u, 0.5f).r, expected, 1e-5f) << mode << " u " << c.u;
      EXPECT_NEAR(tex(0.5f * 0.25f, c.u).r, 0.0f, 1e-5f) << mode << " v " << c.u;  // one row: any v reads it
    }
  }
}

// Mitsuba 0.x's "zero" and "one": the image inside [0, 1], a constant
// outside it, bilinear filtering blending the border toward it.
TEST(BitmapTexture, ZeroAndOneReadAConstantOutsideTheImage) {
  const auto file = write_image("row.exr", 4, 1, 1, {0.5f, 1.5f, 2.5f, 3.5f}, OIIO::TypeDesc::FLOAT);
  for (const char* mode : {"zero", "one"}) {
    const float outside = std::string(mode) == "one" ? 1.0f : 0.0f;
    const TextureProbe tex(bitmap_xml(file, option("filter_type", "nearest") + option("wrap_mode", mode)));
    EXPECT_NEAR(tex(0.6f, 0.5f).r, 2.5f, 1e-5f) << mode;
    EXPECT_NEAR(tex(0.1f, 0.5f).g, 0.5f, 1e-5f) << mode;
    for (float u : {1.1f, -0.1f, 7.3f, -2.6f}) EXPECT_EQ(tex(u, 0.5f), Color(outside)) << mode << " u " << u;
    EXPECT_EQ(tex(0.6f, 1.2f), Color(outside)) << mode;
    const TextureProbe smooth(bitmap_xml(file, option("wrap_mode", mode)));
    EXPECT_NEAR(smooth(0.0f, 0.5f).r, 0.5f * (0.5f + outside), 1e-5f) << mode;  // half way to the constant
  }
}

// wrap_mode_u and wrap_mode_v (0.x's wrapModeU and wrapModeV) each
// override wrap_mode along one axis.
TEST(BitmapTexture, EachAxisWrapsApart) {
  const TextureProbe tex(bitmap_xml(
      quad(), option("filter_type", "nearest") + option("wrap_mode_u", "clamp") + option("wrap_mode_v", "repeat")));
  EXPECT_NEAR(tex(1.3f, 0.25f).r, 2.0f, 1e-5f);  // clamped to the right column
  EXPECT_NEAR(tex(0.25f, 1.3f).r, 1.0f, 1e-5f);  // v 0.3: the top row again
  EXPECT_NEAR(tex(-0.2f, 0.75f).r, 4.0f, 1e-5f);
  const TextureProbe mixed(bitmap_xml(
      quad(), option("filter_type", "nearest") + option("wrap_mode", "mirror") + option("wrap_mode_v", "zero")));
  EXPECT_NEAR(mixed(1.3f, 0.25f).r, 2.0f, 1e-5f);   // u mirrored to 0.7
  EXPECT_NEAR(mixed(-0.3f, 0.75f).r, 4.0f, 1e-5f);  // u mirrored to 0.3
  EXPECT_EQ(mixed(0.25f, 1.3f), Color(0.0f));
}

// 0.x's `channel`: one named channel (any case) as a grey texture; alpha is
// never decoded, the colour channels of an 8-bit image are.
TEST(BitmapTexture, ChannelMakesAGreyTextureOfOneChannel) {
  const auto rgba = write_image("channels.exr", 1, 1, 4, {0.1f, 0.2f, 0.3f, 0.4f}, OIIO::TypeDesc::FLOAT);
  const Color alpha = TextureProbe(bitmap_xml(rgba, option("channel", "a")))(0.5f, 0.5f);
  EXPECT_NEAR(alpha.r, 0.4f, 1e-6f);
  EXPECT_EQ(alpha.r, alpha.g);
  EXPECT_EQ(alpha.r, alpha.b);
  EXPECT_NEAR(TextureProbe(bitmap_xml(rgba, option("channel", "G")))(0.5f, 0.5f).b, 0.2f, 1e-6f);
  const auto rgb = write_image("channels.png", 1, 1, 3, bytes({64, 128, 200}), OIIO::TypeDesc::UINT8);
  const Color green = TextureProbe(bitmap_xml(rgb, option("channel", "g")))(0.5f, 0.5f);
  EXPECT_NEAR(green.r, srgb_eotf(128 / 255.0), 1e-6);
  EXPECT_EQ(green.r, green.b);
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><shape type='rectangle'><bsdf type='diffuse'>" +
                               bitmap_xml(rgba, option("channel", "z")) + "</bsdf></shape></scene>"),
              testing::HasSubstr("'channel' of texture 'bitmap': image '" + rgba.string() +
                                 "' has no channel 'z' (it has R, G, B, A)"));
}

TEST(BitmapTexture, MeanIsTheImageAverage) {
  const PluginInfo* info = Registry::instance().find("texture", "bitmap");
  ASSERT_TRUE(info);
  Properties props(*info, {"test.xml", 1});
  props.set("filename", {ValueKind::String, quad().string(), {"test.xml", 1}});
  const auto tex = std::dynamic_pointer_cast<Texture>(info->create(props));
  ASSERT_TRUE(tex);
  EXPECT_NEAR(tex->mean().r, (1 + 2 + 4 + 8) / 4.0f, 1e-6f);
  EXPECT_NEAR(tex->mean().g, tex->mean().r, 1e-6f);
  // Under repeat, the bilinear texture's average over the unit square is the pixel average.
  double sum = 0;
  const int n = 64;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) sum += tex->eval({(i + 0.5f) / n, (j + 0.5f) / n}).r;
  EXPECT_NEAR(sum / (n * n), 15.0 / 4, 1e-4);
}

TEST(BitmapTexture, UvTransform) {
  const TextureProbe tex(bitmap_xml(
      quad(), option("filter_type", "nearest") + "<transform name='to_uv'><scale x='0.5' y='0.5'/></transform>"));
  EXPECT_NEAR(tex(0.9f, 0.9f).r, 1.0f, 1e-5f);  // (0.45, 0.45): top-left
  EXPECT_NEAR(tex(1.9f, 0.9f).r, 2.0f, 1e-5f);
}

TEST(BitmapTexture, BadInput) {
  const std::string missing = (image_dir() / "no_such_image.png").string();
  const std::string msg = test::load_error("<scene version='3.0.0'>\n<shape type='rectangle'><bsdf type='diffuse'>\n" +
                                           bitmap_xml(missing) + "</bsdf></shape></scene>");
  EXPECT_THAT(msg, testing::HasSubstr("test.xml:3"));
  EXPECT_THAT(msg, testing::HasSubstr("no_such_image.png"));
  EXPECT_THAT(msg, testing::HasSubstr("filename"));

  const fs::path junk = image_dir() / "junk.png";
  {
    std::FILE* f = std::fopen(junk.string().c_str(), "w");
    std::fputs("not an image", f);
    std::fclose(f);
  }
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><shape type='rectangle'><bsdf type='diffuse'>" +
                               bitmap_xml(junk) + "</bsdf></shape></scene>"),
              testing::HasSubstr("junk.png"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><shape type='rectangle'><bsdf type='diffuse'>" +
                               bitmap_xml(quad(), option("wrap_mode", "wrap")) + "</bsdf></shape></scene>"),
              testing::HasSubstr("wrap_mode"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><shape type='rectangle'><bsdf type='diffuse'>" +
                               bitmap_xml(quad(), option("wrap_mode_v", "tile")) + "</bsdf></shape></scene>"),
              testing::HasSubstr("'wrap_mode_v' of texture 'bitmap': unknown wrap mode 'tile' (accepted: repeat, "
                                 "mirror, clamp, zero, one)"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><shape type='rectangle'><bsdf type='diffuse'>" +
                               bitmap_xml(quad(), option("filter_type", "trilinear")) + "</bsdf></shape></scene>"),
              testing::HasSubstr("filter_type"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><shape type='rectangle'><bsdf type='diffuse'>"
                               "<texture type='bitmap' name='reflectance'/></bsdf></shape></scene>"),
              testing::HasSubstr("filename"));
}

TEST(CheckerboardTexture, PatternFollowsMitsuba) {
  const TextureProbe tex("<texture type='checkerboard' name='reflectance'/>");
  EXPECT_NEAR(tex(0.25f, 0.25f).r, 0.4f, 1e-6f);
  EXPECT_NEAR(tex(0.75f, 0.75f).r, 0.4f, 1e-6f);
  EXPECT_NEAR(tex(0.75f, 0.25f).r, 0.2f, 1e-6f);
  EXPECT_NEAR(tex(0.25f, 0.75f).r, 0.2f, 1e-6f);
  EXPECT_NEAR(tex(1.25f, 0.25f).r, 0.4f, 1e-6f);   // repeats
  EXPECT_NEAR(tex(-0.25f, 0.25f).r, 0.2f, 1e-6f);  // frac(-0.25) = 0.75
  EXPECT_NEAR(tex(0.5f, 0.5f).r, 0.4f, 1e-6f);     // 0.5 belongs to the lower half
}

TEST(CheckerboardTexture, ColoursAndTransformAsDiffuseReflectance) {
  const auto bsdf = test::make_bsdf(
      "<bsdf type='diffuse'><texture type='checkerboard' name='reflectance'>"
      "<rgb name='color0' value='0.9, 0.1, 0.1'/><rgb name='color1' value='0.1, 0.1, 0.9'/>"
      "<transform name='to_uv'><scale x='2' y='2'/></transform></texture></bsdf>");
  const Vec3 wo = test::direction(0.4f), wi = test::direction(0.9f, 2.0f);
  const auto f = [&](float u, float v) { return bsdf->eval({TransportMode::Radiance, {u, v}}, wo, wi) * kPi; };
  expect_color_near(f(0.1f, 0.1f), Color(0.9f, 0.1f, 0.1f), 1e-6f);
  expect_color_near(f(0.3f, 0.1f), Color(0.1f, 0.1f, 0.9f), 1e-6f);
  expect_color_near(f(0.3f, 0.3f), Color(0.9f, 0.1f, 0.1f), 1e-6f);
  // Sampling sees the same texture value as eval.
  const auto c = test::check_samples(*bsdf, wo, {TransportMode::Radiance, {0.3f, 0.1f}}, 500);
  EXPECT_LT(c.max_f_error, 1e-6);
}

// Mitsuba 0.x's scale texture: the nested texture times the factor, its
// checks where they were.
TEST(ScaleTexture, ScalesTheNestedTexture) {
  const TextureProbe scaled(
      "<texture type='scale' name='reflectance'><float name='scale' value='0.4'/><texture type='checkerboard'>"
      "<rgb name='color0' value='0.5, 0.25, 1'/><rgb name='color1' value='0.1'/></texture></texture>");
  expect_color_near(scaled(0.25f, 0.25f), Color(0.2f, 0.1f, 0.4f), 1e-6f);
  expect_color_near(scaled(0.75f, 0.25f), Color(0.04f), 1e-6f);
  expect_color_near(scaled(0.75f, 0.75f), Color(0.2f, 0.1f, 0.4f), 1e-6f);
  EXPECT_THAT(
      test::load_error("<scene version='3.0.0'>\n<texture type='scale'>\n<float name='scale' value='-1'/>"
                       "<texture type='checkerboard'/></texture></scene>"),
      testing::HasSubstr("test.xml:3: parameter 'scale' of texture 'scale': must be a finite number of 0 or more"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'>\n<texture type='scale'/></scene>"),
              testing::HasSubstr("test.xml:2: a scale texture needs a nested <texture> to scale"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
