// A loaded scene and its integrator stay const while they render: every
// render keeps its state (photon maps, rounds, sppm's pixels) in an object
// of its own, so two renders of one scene can run at once and give what
// they give alone.

#include <gtest/gtest.h>

#include <cstring>
#include <thread>

#include "core/loader/scene_loader.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

bool same_pixels(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

TEST(ConcurrentRenders, TwoRendersOfOneSceneGiveTheImagesOfSeparateRuns) {
  const std::string glass = std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box-glass.xml";
  for (const char* integrator : {"photon:photons=2000", "sppm:photons=2000", "bdpt"}) {
    auto scene = load_scene(glass, {{"res", "24"}});
    scene.integrator = make_integrator(integrator);
    const auto alone_a = test::render_scene(scene, 3, 21, 1).resolve();
    const auto alone_b = test::render_scene(scene, 4, 22, 1).resolve();
    std::vector<float> a, b;
    std::thread first([&] { a = test::render_scene(scene, 3, 21, 1).resolve(); });
    std::thread second([&] { b = test::render_scene(scene, 4, 22, 1).resolve(); });
    first.join();
    second.join();
    EXPECT_TRUE(same_pixels(a, alone_a)) << integrator;
    EXPECT_TRUE(same_pixels(b, alone_b)) << integrator;
    EXPECT_FALSE(same_pixels(a, b)) << integrator;
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
