// A render's layers are made a band of rows at a time as the file is
// written, the first-hit layers evaluated per band: any split into bands
// must give the image of one band.

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

#include "core/job/render_job.h"
#include "core/job/render_outputs.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// A render of the Cornell box and its first-hit layers.
struct Rendered {
  RenderJob job;
  RenderResult result;
  std::optional<FirstHitLayers> first_hit;
};

std::unique_ptr<Rendered> render_box(int res, uint32_t spp, const std::string& name = "cornell-box") {
  RenderSettings settings;
  settings.spp = spp;
  settings.seed = 5;
  auto r = std::make_unique<Rendered>(Rendered{
      RenderJob(
          load_scene(std::string(CAUSTICA_SOURCE_DIR) + "/scenes/" + name + ".xml", {{"res", std::to_string(res)}}),
          settings),
      {FilmBuffer(1, 1, {}), {}},
      std::nullopt});
  r->result = r->job.run();
  if (auto layers = r->job.first_hit_layers(r->result)) r->first_hit.emplace(std::move(*layers));
  return r;
}

TEST(RenderLayers, BandsOfAnySizeMakeTheWholeImage) {
  const auto r = render_box(8, 3);
  ASSERT_TRUE(r->first_hit);
  const RenderLayers layers(r->result.film, &*r->first_hit, true, true);
  const Image whole = layers.image();
  const size_t row = size_t(whole.width) * whole.channels.size();
  std::vector<float> banded(whole.pixels.size());
  for (const auto& [begin, end] : {std::pair{0, 3}, {3, 4}, {4, 8}})
    layers.rows().fill(begin, end, banded.data() + size_t(begin) * row);
  EXPECT_EQ(banded, whole.pixels);
  // The albedo of the white walls and boxes is not zero, the layers were evaluated.
  const int albedo = whole.channel_index("albedo.R");
  ASSERT_GE(albedo, 0);
  EXPECT_GT(whole.pixels[4 * row + 4 * whole.channels.size() + size_t(albedo)], 0.1f);
}

// A medium's null boundary shows nothing: the layers of the fog box are
// those of the plain box, the walls behind the boundary.
TEST(RenderLayers, NullSurfacesAreLookedThrough) {
  const auto fog = render_box(8, 1, "cornell-box-fog"), plain = render_box(8, 1);
  ASSERT_TRUE(fog->first_hit && plain->first_hit);
  const Image a = RenderLayers(fog->result.film, &*fog->first_hit, true, true).image();
  const Image b = RenderLayers(plain->result.film, &*plain->first_hit, true, true).image();
  for (const char* channel : {"albedo.R", "depth.T", "normal.Z"}) {
    const int ia = a.channel_index(channel), ib = b.channel_index(channel);
    ASSERT_GE(ia, 0);
    for (int p = 0; p < 64; ++p)
      EXPECT_NEAR(a.pixels[p * a.channels.size() + ia], b.pixels[p * b.channels.size() + ib], 1e-3f)
          << channel << " at pixel " << p;
  }
}

// The first-hit layers are evaluated only to be written: a scan for values
// out of half's range leaves them out, and a half file keeps them in float.
TEST(RenderLayers, EvaluatedLayersAreWrittenInFloatAndNotScanned) {
  const auto r = render_box(4, 1);
  ASSERT_TRUE(r->first_hit);
  const RenderLayers layers(r->result.film, &*r->first_hit, true, true);
  std::vector<std::string> float_only = layers.rows().float_only;
  std::sort(float_only.begin(), float_only.end());
  EXPECT_EQ(float_only.size(), 7u + 7 * 6 + 6 + 1);  // resolved, raw sums, raw weight, raw count
  EXPECT_TRUE(std::binary_search(float_only.begin(), float_only.end(), "depth.T"));
  EXPECT_FALSE(std::binary_search(float_only.begin(), float_only.end(), "R"));
  const uint64_t before = r->job.scene()->layer_rays_traced();
  layers.extreme_values();
  EXPECT_EQ(r->job.scene()->layer_rays_traced(), before);
  const RenderLayers merged(r->result.film, static_cast<const FilmBuffer*>(nullptr), true, true);
  EXPECT_TRUE(merged.rows().float_only.empty());
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
