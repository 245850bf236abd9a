#include "core/geometry/ray_log.h"

#include <gtest/gtest.h>

#include "core/loader/scene_loader.h"
#include "core/render/renderer.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

TEST(RayLog, RecordsEveryRayARenderTraces) {
  const auto scene = load_scene(std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box.xml", {{"res", "8"}});
  RayLog log;
  scene->set_ray_log(&log);
  FilmBuffer film(8, 8, scene.integrator->channels());
  RenderOptions options;
  options.spp = 2;
  options.threads = 2;
  const RenderStats stats = render(*scene, *scene.integrator, options, film);
  scene->set_ray_log(nullptr);

  const auto entries = log.entries();
  EXPECT_EQ(entries.size(), stats.rays);
  size_t shadow = 0;
  for (const RayLog::Entry& e : entries) shadow += e.shadow;
  EXPECT_GT(shadow, 0u);                           // next-event estimation
  EXPECT_GT(entries.size() - shadow, 8u * 8 * 2);  // camera rays and bounces

  render(*scene, *scene.integrator, options, film);
  EXPECT_EQ(log.entries().size(), entries.size());  // detached: nothing more is recorded
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
