// The rays a render reports are the integrator's, each once: the first-hit
// layers re-trace one camera ray per sample of their first kAovSamples and
// count it apart, so rendering them changes nothing in the integrator's
// count.

#include <gtest/gtest.h>

#include "core/loader/scene_loader.h"
#include "core/render/renderer.h"
#include "core/render/standard_aovs.h"

namespace caustica {
namespace {

TEST(RayCount, FirstHitLayersAreCountedApartFromTheIntegratorsRays) {
  const auto scene = load_scene(std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box.xml", {{"res", "8"}});
  RenderOptions options;
  options.spp = 20;
  options.threads = 2;
  FilmBuffer plain(8, 8, scene.integrator->channels()), beauty(8, 8, scene.integrator->channels());
  FilmBuffer layers(8, 8, standard_aov_channels(false));
  const RenderStats without = render(*scene, *scene.integrator, options, plain);
  const RenderStats with = render(*scene, *scene.integrator, options, beauty, &layers);
  EXPECT_EQ(with.rays, without.rays);
  EXPECT_GT(with.rays, 8u * 8 * 20);  // camera rays, bounces and shadow rays
  EXPECT_EQ(without.layer_rays, 0u);
  EXPECT_EQ(with.layer_rays, 8u * 8 * 16);  // the first 16 samples of each of the 64 pixels
}

}  // namespace
}  // namespace caustica
