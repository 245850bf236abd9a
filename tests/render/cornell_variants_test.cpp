// Regression tests for the Cornell-box family: every pixel finite, and the
// image in agreement with a stored reference of the project's own (24x24,
// 16384 spp, made by scripts/make-test-references.sh).
//
// Agreement is judged per region of 4x4 pixels and channel by a z-test of
// the difference of the means, at significance 1% Sidak-corrected over all
// regions, channels and scenes. The per-sample variance comes from the
// reference (16 times as many samples): caustic paths are rare, and a short
// render's own variance estimate misses them and would understate its
// error. 1024 samples per pixel keep the sum of rare bright caustic samples
// close enough to normal for a z-test. Single dark pixels (self-intersection speckles) are caught by a
// one-sided per-pixel bound. Seeds are fixed.

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "core/image/image_input.h"
#include "tests/support/chi2.h"
#include "tests/support/test_scenes.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

constexpr int kRes = 24, kRegion = 4, kSpp = 1024;
const char* const kScenes[] = {"cornell-box",        "cornell-box-glass", "cornell-box-mirror",
                               "cornell-box-glossy", "cornell-box-phong", "cornell-box-textured"};
constexpr int kTests = int(std::size(kScenes)) * (kRes / kRegion) * (kRes / kRegion) * 3;

class CornellVariant : public testing::TestWithParam<const char*> {};

TEST_P(CornellVariant, FiniteAndAgreesWithTheReference) {
  const std::string name = GetParam();
  const auto scene =
      load_scene(std::string(CAUSTICA_SOURCE_DIR) + "/scenes/" + name + ".xml", {{"res", std::to_string(kRes)}});
  const FilmBuffer film = test::render_scene(scene, kSpp, 1);
  EXPECT_EQ(film.dropped_samples(), 0u);
  const auto img = film.resolve();
  for (float v : img) ASSERT_TRUE(std::isfinite(v)) << name;

  std::map<std::string, std::string> metadata;
  const Image ref = read_image(std::string(CAUSTICA_SOURCE_DIR) + "/tests/data/references/" + name + ".exr", &metadata);
  ASSERT_EQ(ref.width, kRes);
  const double ref_spp = std::stod(metadata["caustica:spp"]);
  // Variance of the test's pixel mean plus the reference's, from the
  // reference's estimate of the variance of one sample.
  const double variance_scale = ref_spp / kSpp + 1;
  const auto channel = [&](const std::string& c) {
    return size_t(std::find(ref.channels.begin(), ref.channels.end(), c) - ref.channels.begin());
  };
  const size_t nc = ref.channels.size();
  const size_t rgb[3] = {channel("R"), channel("G"), channel("B")};
  const size_t ref_var[3] = {channel("variance.R"), channel("variance.G"), channel("variance.B")};
  ASSERT_LT(ref_var[2], nc);

  const double z_region = test::two_sided_z_critical(test::sidak_alpha(0.01, kTests));
  for (int ry = 0; ry < kRes; ry += kRegion)
    for (int rx = 0; rx < kRes; rx += kRegion)
      for (int c = 0; c < 3; ++c) {
        double diff = 0, variance = 0;
        for (int y = ry; y < ry + kRegion; ++y)
          for (int x = rx; x < rx + kRegion; ++x) {
            const size_t p = size_t(y) * kRes + x;
            const double test_value = img[p * 3 + c], ref_value = ref.pixels[p * nc + rgb[c]];
            const double pixel_variance = ref.pixels[p * nc + ref_var[c]] * variance_scale;
            diff += test_value - ref_value;
            variance += pixel_variance;
            // A speckle: far darker than the reference allows.
            EXPECT_GT(test_value, ref_value - 8 * std::sqrt(pixel_variance) - 1e-4)
                << name << " pixel (" << x << ", " << y << ") channel " << c;
          }
        const double z = variance > 0 ? diff / std::sqrt(variance) : (std::abs(diff) < 1e-6 ? 0 : 1e9);
        EXPECT_LT(std::abs(z), z_region) << name << " region (" << rx << ", " << ry << ") channel " << c;
      }
}

INSTANTIATE_TEST_SUITE_P(Scenes, CornellVariant, testing::ValuesIn(kScenes), test::scene_test_name);

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
