#include <gtest/gtest.h>

#include <cstring>

#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

const std::string kScene = std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box.xml";

LoadedScene small_cornell_box() { return load_scene(kScene, {{"res", "40"}, {"spp", "4"}}); }

TEST(Determinism, SameSeedIsBitIdenticalForOneAndTwoThreads) {
  const auto scene = small_cornell_box();
  const auto one = test::render_scene(scene, 6, 11, 1).resolve();
  const auto two = test::render_scene(scene, 6, 11, 2).resolve();
  ASSERT_EQ(one.size(), two.size());
  EXPECT_EQ(0, std::memcmp(one.data(), two.data(), one.size() * sizeof(float)));
  const auto other_seed = test::render_scene(scene, 6, 12, 2).resolve();
  EXPECT_NE(0, std::memcmp(one.data(), other_seed.data(), one.size() * sizeof(float)));
}

// Splats are made by whichever thread renders a tile and enter the film in
// tile order; chunks of tiles differ in size with the thread count (8 for
// one thread, 12 for three), which must not matter either.
TEST(Determinism, SplattingIntegratorsAreBitIdenticalForAnyThreadCount) {
  for (const char* integrator : {"ptracer", "bdpt"}) {
    const auto scene = load_scene(kScene, {{"res", "80"}, {"integrator", integrator}});
    const auto one = test::render_scene(scene, 2, 11, 1).resolve();
    const auto three = test::render_scene(scene, 2, 11, 3).resolve();
    ASSERT_EQ(one.size(), three.size());
    EXPECT_EQ(0, std::memcmp(one.data(), three.data(), one.size() * sizeof(float))) << integrator;
  }
}

// Photon rounds are traced in parallel blocks joined in order, and sppm's
// pixels keep their own state: both bit-identical for any thread count.
TEST(Determinism, PhotonPassesAreBitIdenticalForAnyThreadCount) {
  const std::string glass = std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box-glass.xml";
  for (const char* integrator : {"photon", "sppm"}) {
    const auto scene = load_scene(glass, {{"res", "32"}, {"integrator", integrator}});
    const auto one = test::render_scene(scene, 3, 11, 1).resolve();
    const auto three = test::render_scene(scene, 3, 11, 3).resolve();
    ASSERT_EQ(one.size(), three.size());
    EXPECT_EQ(0, std::memcmp(one.data(), three.data(), one.size() * sizeof(float))) << integrator;
  }
}

// With one sample per pixel the filter weight cancels, so the image holds
// exactly the values a replayed sample produces.
TEST(Determinism, ReplayedSampleIsTheOneInTheImage) {
  const auto scene = load_scene(kScene, {{"res", "16"}});
  const auto img = test::render_scene(scene, 1, 5).resolve();
  for (Vec2i p : {Vec2i{3, 4}, Vec2i{15, 0}, Vec2i{8, 12}}) {
    const auto v = replay_sample(*scene, *scene.integrator, p, 0, 5).values;
    for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(v[c], img[(p.y * 16 + p.x) * 3 + c]);
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
