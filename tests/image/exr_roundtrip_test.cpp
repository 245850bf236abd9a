#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/image/image_input.h"
#include "core/image/image_output.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

Image layered_image() {
  Image image{5,
              3,
              {"R", "G", "B", "albedo.R", "albedo.G", "albedo.B", "normal.X", "normal.Y", "normal.Z", "depth.T",
               "variance.R", "variance.G", "variance.B", "samples.Y"},
              {}};
  for (size_t i = 0; i < size_t(5 * 3 * 14); ++i) image.pixels.push_back(0.25f * float(i % 97) - 3.0f);
  return image;
}

// OpenEXR keeps channels sorted by name, so layers are compared by name.
float channel(const Image& image, size_t pixel, const std::string& name) {
  const size_t c = std::find(image.channels.begin(), image.channels.end(), name) - image.channels.begin();
  EXPECT_LT(c, image.channels.size()) << name;
  return c < image.channels.size() ? image.pixels[pixel * image.channels.size() + c] : NAN;
}

void expect_same_layers(const Image& back, const Image& image, float relative_tolerance) {
  ASSERT_EQ(back.channels.size(), image.channels.size());
  for (size_t p = 0; p < size_t(image.width) * image.height; ++p)
    for (const std::string& name : image.channels) {
      const float v = channel(image, p, name);
      EXPECT_NEAR(channel(back, p, name), v, std::abs(v) * relative_tolerance) << name << " at pixel " << p;
    }
}

TEST(ExrRoundTrip, EveryLayerAndMetadataKeyFloat) {
  const auto path = std::filesystem::temp_directory_path() / "caustica_roundtrip.exr";
  const Image image = layered_image();
  const std::map<std::string, std::string> metadata = {
      {"caustica:scene", "box.xml"}, {"caustica:integrator", "path max_depth=-1"},
      {"caustica:spp", "64"},        {"caustica:seconds", "1.5"},
      {"caustica:seed", "7"},        {"caustica:version", "0.1.0"}};
  write_exr(path, image, metadata, false);
  std::map<std::string, std::string> read_metadata;
  const Image back = read_image(path, &read_metadata);
  EXPECT_EQ(back.width, 5);
  EXPECT_EQ(back.height, 3);
  expect_same_layers(back, image, 0);
  for (const auto& [key, value] : metadata) EXPECT_EQ(read_metadata[key], value) << key;
}

TEST(ExrRoundTrip, HalfKeepsElevenBits) {
  const auto path = std::filesystem::temp_directory_path() / "caustica_roundtrip_half.exr";
  const Image image = layered_image();
  write_exr(path, image, {}, true);
  expect_same_layers(read_image(path), image, 1e-3f);
}

TEST(ImageInput, MissingFileNamesIt) {
  try {
    read_image("/nonexistent/render.exr");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot read image '/nonexistent/render.exr'"), std::string::npos);
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
