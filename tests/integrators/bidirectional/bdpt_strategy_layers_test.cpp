// bdpt's per-strategy layers: one per (s, t) for paths up to the requested
// length, in a fixed order, summing to the beauty when they cover every
// path the integrator renders; and the parameters' bad values.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/loader/scene_loader.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using testing::HasSubstr;

const std::string kScene = std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box-glass.xml";

TEST(BdptStrategyLayers, NamedByStrategyInOrder) {
  const auto scene = test::scene_from_xml(
      "<scene version='3.0.0'><integrator type='bdpt'><integer name='strategy_layers' "
      "value='2'/></integrator></scene>");
  EXPECT_THAT(scene.integrator->channels(),
              testing::ElementsAre("R", "G", "B", "s0t2.R", "s0t2.G", "s0t2.B", "s1t1.R", "s1t1.G", "s1t1.B", "s0t3.R",
                                   "s0t3.G", "s0t3.B", "s1t2.R", "s1t2.G", "s1t2.B", "s2t1.R", "s2t1.G", "s2t1.B"));
}

// With max_depth equal to the layers' reach, every contribution lands in
// exactly one layer, splats included.
TEST(BdptStrategyLayers, SumToTheBeauty) {
  auto scene = load_scene(kScene, {{"res", "24"}, {"integrator", "bdpt"}, {"max_depth", "3"}});
  scene.integrator = test::scene_from_xml(
                         "<scene version='3.0.0'><integrator type='bdpt'><integer "
                         "name='max_depth' value='3'/><integer name='strategy_layers' "
                         "value='3'/></integrator></scene>")
                         .integrator;
  const auto channels = scene.integrator->channels();
  ASSERT_EQ(channels.size(), 3u + 3 * (2 + 3 + 4));
  const auto img = test::render_scene(scene, 8, 3).resolve();
  const size_t nc = channels.size();
  double beauty = 0, layers = 0;
  for (size_t p = 0; p < img.size() / nc; ++p)
    for (int c = 0; c < 3; ++c) {
      double sum = 0;
      for (size_t l = 3 + c; l < nc; l += 3) sum += img[p * nc + l];
      EXPECT_NEAR(sum, img[p * nc + c], 1e-4 * (1 + std::abs(img[p * nc + c]))) << "pixel " << p;
      beauty += img[p * nc + c];
      layers += sum;
    }
  EXPECT_GT(beauty, 0);
  EXPECT_NEAR(layers, beauty, 1e-4 * beauty);
  // The caustic under the sphere comes from light tracing: some light lands
  // in layers with t = 1.
  double light_traced = 0;
  for (size_t l = 0; l < nc; ++l)
    if (channels[l].find("t1.") != std::string::npos)
      for (size_t p = 0; p < img.size() / nc; ++p) light_traced += img[p * nc + l];
  EXPECT_GT(light_traced, 0.01 * beauty);
}

// The sphere's caustic on the floor, where it touches (light, glass, glass,
// floor, camera), is found far better by light tracing (s4t1) than by
// camera paths that hit the light through the sphere (s0t5): measured
// across the chain, the weights give it to light tracing. Densities taken
// on the sphere's surface, a centimetre from the floor there, gave two
// thirds of it to s0t5, whose rare hits were the image's fireflies.
TEST(BdptStrategyLayers, SpecularChainsLeaveTheCausticToLightTracing) {
  auto scene = load_scene(kScene, {{"res", "32"}});
  scene.integrator = test::scene_from_xml(
                         "<scene version='3.0.0'><integrator type='bdpt'><integer name='strategy_layers' "
                         "value='4'/></integrator></scene>")
                         .integrator;
  const auto channels = scene.integrator->channels();
  const auto img = test::render_scene(scene, 64, 1).resolve();
  const size_t nc = channels.size();
  // The four-segment layers summed over the caustic's pixels.
  const auto layer = [&](const std::string& name) {
    const size_t first = size_t(std::find(channels.begin(), channels.end(), name + ".R") - channels.begin());
    EXPECT_LT(first, nc) << name;
    double sum = 0;
    for (int y = 26; y < 31; ++y)
      for (int x = 17; x < 26; ++x)
        for (size_t c = 0; c < 3; ++c) sum += img[(size_t(y) * 32 + x) * nc + first + c];
    return sum;
  };
  double four_segments = 0;
  for (const char* name : {"s0t5", "s1t4", "s2t3", "s3t2", "s4t1"}) four_segments += layer(name);
  ASSERT_GT(four_segments, 0);
  EXPECT_GT(layer("s4t1") / four_segments, 0.5);
  EXPECT_LT(layer("s0t5") / four_segments, 0.05);
}

TEST(BdptStrategyLayers, BadParameters) {
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><integrator type='bdpt'>\n"
                               "<string name='mis' value='cubic'/></integrator></scene>"),
              HasSubstr("test.xml:2: parameter 'mis' of integrator 'bdpt': must be power or balance, not 'cubic'"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><integrator type='bdpt'>\n"
                               "<integer name='strategy_layers' value='13'/></integrator></scene>"),
              HasSubstr("test.xml:2: parameter 'strategy_layers' of integrator 'bdpt': must be between 0 and 12"));
  EXPECT_THAT(
      test::load_error("<scene version='3.0.0'><integrator type='ptracer'>\n"
                       "<integer name='max_depth' value='-2'/></integrator></scene>"),
      HasSubstr("test.xml:2: parameter 'max_depth' of integrator 'ptracer': must be -1 (unlimited) or at least 0"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><integrator type='bdpt'>\n"
                               "<float name='rr_max_survival' value='0'/></integrator></scene>"),
              HasSubstr("test.xml:2: parameter 'rr_max_survival' of integrator 'bdpt': must be in (0, 1]"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><integrator type='path'>\n"
                               "<float name='rr_threshold' value='0'/></integrator></scene>"),
              HasSubstr("test.xml:2: parameter 'rr_threshold' of integrator 'path': must be positive (1e30 for "
                        "roulette at any throughput)"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
