// The rays a render reports are the integrator's, each once: the first-hit
// layers re-trace one camera ray per sample of their first kAovSamples when
// the image is written and count it apart, so they change nothing in the
// integrator's count.

#include <gtest/gtest.h>

#include "core/loader/scene_loader.h"
#include "core/render/first_hit_layers.h"
#include "core/render/renderer.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

TEST(RayCount, FirstHitLayersAreCountedApartFromTheIntegratorsRays) {
  const auto scene = load_scene(std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box.xml", {{"res", "8"}});
  RenderOptions options;
  options.spp = 20;
  options.threads = 2;
  FilmBuffer beauty(8, 8, scene.integrator->channels());
  const uint64_t layer_rays_before = scene->layer_rays_traced();
  const RenderStats stats = render(*scene, *scene.integrator, options, beauty);
  EXPECT_GT(stats.rays, 8u * 8 * 20);  // camera rays, bounces and shadow rays
  EXPECT_EQ(scene->layer_rays_traced(), layer_rays_before);
  const uint64_t rays_before = scene->rays_traced();
  const FirstHitLayers layers(*scene, options.seed, 0, beauty, 2);
  const FilmBuffer top = layers.evaluate(0, 5), bottom = layers.evaluate(5, 8);
  EXPECT_EQ(scene->rays_traced(), rays_before);
  EXPECT_EQ(scene->layer_rays_traced() - layer_rays_before, 8u * 8 * 16);  // the first 16 samples of 64 pixels
  EXPECT_EQ(top.height(), 5);
  EXPECT_EQ(bottom.sample_count({7, 2}), 16u);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
