// The compatibility corpus (scenes/compat): scene files in the styles of
// real Mitsuba 3 and 0.x files, each rendered at its own tiny size, and the
// looks Mitsuba's documentation implies checked where they are cheap.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/loader/scene_loader.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

const std::filesystem::path kCorpus = std::filesystem::path(CAUSTICA_SOURCE_DIR) / "scenes" / "compat";

std::vector<std::filesystem::path> corpus_files(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> out;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    if (entry.path().extension() == ".xml") out.push_back(entry.path());
  std::sort(out.begin(), out.end());
  return out;
}

// A rendered image: pixels of `channels` floats, row by row.
struct Image {
  std::vector<float> values;
  int width, height;
  size_t channels;
  float at(int x, int y, size_t c) const { return values[(size_t(y) * width + x) * channels + c]; }
  // The mean of channel c over the columns [x0, x1).
  double column_mean(int x0, int x1, size_t c) const {
    double sum = 0;
    for (int y = 0; y < height; ++y)
      for (int x = x0; x < x1; ++x) sum += at(x, y, c);
    return sum / (double(x1 - x0) * height);
  }
};

Image render(const std::string& name, uint32_t spp) {
  const LoadedScene scene = load_scene(kCorpus / name);
  const FilmBuffer film = test::render_scene(scene, spp, 1, 1);
  return {film.resolve(), film.width(), film.height(), film.channel_count()};
}

// Every file loads and renders to finite values, not all zero.
TEST(CompatCorpus, EveryFileRenders) {
  const auto files = corpus_files(kCorpus);
  EXPECT_GE(files.size(), 20u);
  for (const auto& file : files) {
    const Image image = render(file.filename().string(), 2);
    EXPECT_LE(image.width * image.height, 32 * 32) << file;
    EXPECT_TRUE(std::all_of(image.values.begin(), image.values.end(), [](float v) { return std::isfinite(v); }))
        << file;
    EXPECT_TRUE(std::any_of(image.values.begin(), image.values.end(), [](float v) { return v != 0; })) << file;
  }
}

// A diffuse sphere of reflectance 1 under a uniform sky of radiance 1
// vanishes: every pixel's expected value is 1, and the image mean (1024
// pixels at 16 spp, Russian roulette its only noise) is 1 within 4
// standard errors of the pixel spread.
TEST(CompatCorpus, TheWhiteFurnaceIsUniform) {
  const Image image = render("furnace-white.xml", 16);
  for (size_t c = 0; c < 3; ++c) {
    double sum = 0, sum2 = 0;
    const int n = image.width * image.height;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        sum += image.at(x, y, c);
        sum2 += image.at(x, y, c) * image.at(x, y, c);
      }
    const double mean = sum / n, error = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
    EXPECT_NEAR(mean, 1, 4 * error + 1e-6) << "channel " << c;
  }
}

// The tutorials' Cornell box: the red wall on the left, the green on the right.
TEST(CompatCorpus, TheCornellBoxHasItsRedWallLeftAndGreenRight) {
  const Image image = render("cbox-m3-tutorial.xml", 16);
  EXPECT_GT(image.column_mean(0, 2, 0), 3 * image.column_mean(0, 2, 1));
  EXPECT_GT(image.column_mean(image.width - 2, image.width, 1), 2 * image.column_mean(image.width - 2, image.width, 0));
}

// A 2700 K black body is orange: red above green above blue.
TEST(CompatCorpus, AWarmBlackBodyLampLooksOrange) {
  const Image image = render("spectral-lamp-blackbody.xml", 16);
  const double r = image.column_mean(0, image.width, 0), g = image.column_mean(0, image.width, 1),
               b = image.column_mean(0, image.width, 2);
  EXPECT_GT(r, 1.5 * g);
  EXPECT_GT(g, 1.5 * b);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
