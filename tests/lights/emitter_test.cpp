// The light interface every integrator relies on: sample_Li agrees with
// pdf_Li, sample_Le with pdf_Le, and power with the emitted flux.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/math/constants.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

LoadedScene light_scene(const std::string& shape) {
  return test::scene_from_xml("<scene version='3.0.0'>" + shape + "</scene>");
}

const std::string kShapes[] = {
    "<shape type='rectangle'><transform name='to_world'><scale x='0.5' y='2'/><rotate x='1' angle='30'/></transform>"
    "<emitter type='area'><rgb name='radiance' value='2'/></emitter></shape>",
    "<shape type='sphere'><float name='radius' value='0.5'/><emitter type='area'><rgb name='radiance' value='2'/>"
    "</emitter></shape>",
    "<shape type='disk'><transform name='to_world'><scale x='0.5' y='1.5'/></transform><emitter type='area'>"
    "<rgb name='radiance' value='2'/></emitter></shape>",
    // A radiance texture: a rectangle's (u, v) spread evenly over its area,
    // so the texture's mean is the emitter's too and power() stays exact.
    "<shape type='rectangle'><transform name='to_world'><rotate x='1' angle='-20'/></transform>"
    "<emitter type='area'><texture type='checkerboard' name='radiance'><float name='color0' value='0.5'/>"
    "<float name='color1' value='3'/><transform name='to_uv'><scale value='3'/></transform></texture>"
    "</emitter></shape>"};

class AreaEmitter : public testing::TestWithParam<std::string> {};

TEST_P(AreaEmitter, SampledDensitiesMatchTheirPdfs) {
  const auto scene = light_scene(GetParam());
  const Emitter& light = *scene->emitters().front();
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> u(0, kOneMinusEpsilon);
  const ReferencePoint ref{{0.3f, 0.2f, 2.5f}, {}, {}};
  int checked = 0;
  for (int i = 0; i < 200; ++i) {
    const auto ls = light.sample_Li(ref, {u(rng), u(rng)});
    if (!ls) continue;
    ++checked;
    const auto hit = scene->intersect({ref.p, ls->wi});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(light.pdf_Li(ref, ls->wi, *hit), ls->pdf, 2e-3f * ls->pdf);
    EXPECT_EQ(ls->Li, light.L(*hit, -ls->wi));

    const auto le = light.sample_Le({u(rng), u(rng)}, {u(rng), u(rng)});
    ASSERT_TRUE(le);
    float pdf_pos = 0, pdf_dir = 0;
    light.pdf_Le(le->ray, le->n, &pdf_pos, &pdf_dir);
    EXPECT_NEAR(pdf_pos, le->pdf_pos, 1e-4f * pdf_pos);
    EXPECT_NEAR(pdf_dir, le->pdf_dir, 1e-4f * pdf_dir);
    EXPECT_GT(dot(le->ray.d, le->n), 0);  // emitted to the lit side
    // The radiance sent is what the surface shows there, seen along the ray.
    const auto back = scene->intersect({le->ray.at(0.01f), -le->ray.d});
    ASSERT_TRUE(back);
    EXPECT_EQ(le->Le, light.L(*back, le->ray.d));
  }
  EXPECT_GT(checked, 50);  // the light faces the reference point
}

// Flux = integral of Le cos over area and hemisphere = pi Le A; the
// estimate from sample_Le's own densities must agree with power().
TEST_P(AreaEmitter, PowerMatchesSampledFlux) {
  const auto scene = light_scene(GetParam());
  const Emitter& light = *scene->emitters().front();
  std::mt19937 rng(4);
  std::uniform_real_distribution<float> u(0, kOneMinusEpsilon);
  double flux = 0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    const auto le = light.sample_Le({u(rng), u(rng)}, {u(rng), u(rng)});
    if (le) flux += le->Le.r * dot(le->ray.d, le->n) / (le->pdf_pos * le->pdf_dir);
  }
  EXPECT_NEAR(flux / n, light.power().r, 0.01 * light.power().r);
}

INSTANTIATE_TEST_SUITE_P(Shapes, AreaEmitter, testing::ValuesIn(kShapes));

TEST(PointEmitter, DeltaLightFallsOffWithDistanceSquared) {
  const auto scene = light_scene(
      "<emitter type='point'><point name='position' value='0, 0, 2'/>"
      "<rgb name='intensity' value='8'/></emitter>");
  const Emitter& light = *scene->emitters().front();
  const auto ls = light.sample_Li({{0, 0, 0}, {}, {}}, {0.5f, 0.5f});
  ASSERT_TRUE(ls);
  EXPECT_TRUE(ls->is_delta);
  EXPECT_FLOAT_EQ(ls->Li.r, 2);
  EXPECT_FLOAT_EQ(ls->wi.z, 1);
  EXPECT_FLOAT_EQ(light.power().r, 8 * 4 * kPi);
  const auto le = light.sample_Le({0.1f, 0.2f}, {0.3f, 0.4f});
  ASSERT_TRUE(le);
  float pdf_pos = 0, pdf_dir = 0;
  light.pdf_Le(le->ray, le->n, &pdf_pos, &pdf_dir);
  EXPECT_EQ(pdf_pos, le->pdf_pos);
  EXPECT_EQ(pdf_dir, le->pdf_dir);
}

// The spot's flux, sampled over its cone, matches its power: the intensity
// integrated with the linear fall-off, 2 pi [1 - (sin c - sin b) / (c - b)].
TEST(SpotEmitter, PowerMatchesSampledFlux) {
  const auto scene = light_scene(
      "<emitter type='spot'><rgb name='intensity' value='3'/><float name='cutoff_angle' value='50'/>"
      "<float name='beam_width' value='10'/><transform name='to_world'><rotate x='1' angle='30'/></transform>"
      "</emitter><shape type='sphere'/>");
  const Emitter& light = *scene->emitters().front();
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0, kOneMinusEpsilon);
  double flux = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const auto le = light.sample_Le({u(rng), u(rng)}, {u(rng), u(rng)});
    if (le) flux += le->Le.r / (le->pdf_pos * le->pdf_dir);
  }
  const double b = 10 * M_PI / 180, c = 50 * M_PI / 180;
  const double expected = 3 * 2 * M_PI * (1 - (std::sin(c) - std::sin(b)) / (c - b));
  EXPECT_NEAR(flux / n, expected, 0.005 * expected);
  EXPECT_NEAR(light.power().r, expected, 1e-4 * expected);
}

// A directional light: every direction it gives is its own, light rays
// start outside the scene's bounding sphere and cross it, and its power is
// the irradiance over the disk they start on.
TEST(DirectionalEmitter, OneDirectionAcrossTheScene) {
  const auto scene = light_scene(
      "<emitter type='directional'><vector name='direction' x='0' y='3' z='-4'/>"
      "<rgb name='irradiance' value='2'/></emitter><shape type='sphere'><float name='radius' value='2'/></shape>");
  const Emitter& light = *scene->emitters().front();
  EXPECT_TRUE(light.is_delta());
  EXPECT_TRUE(scene->infinite_emitters().empty());  // no escaping ray can meet it
  const auto ls = light.sample_Li({{0, 0, 5}, {}, {}}, {0.2f, 0.7f});
  ASSERT_TRUE(ls);
  EXPECT_TRUE(ls->is_delta && ls->is_infinite);
  EXPECT_NEAR(ls->wi.y, -0.6f, 1e-6f);
  EXPECT_NEAR(ls->wi.z, 0.8f, 1e-6f);
  EXPECT_FLOAT_EQ(ls->Li.r, 2);
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> u(0, kOneMinusEpsilon);
  int hits = 0;
  const int n = 4000;
  for (int i = 0; i < n; ++i) {
    const auto le = light.sample_Le({u(rng), u(rng)}, {u(rng), u(rng)});
    ASSERT_TRUE(le);
    EXPECT_NEAR(le->ray.d.y, 0.6f, 1e-6f);
    // Starts outside the sphere of radius 2 (the scene), never inside it.
    EXPECT_GT(length(le->ray.o), 2.0f);
    EXPECT_FLOAT_EQ(light.power().r, le->Le.r / le->pdf_pos);
    hits += bool(scene->intersect(le->ray));
  }
  // The fraction of rays that meet the sphere: its cross-section, pi 2^2,
  // over the disk's area, whose radius is 1.01 times the bounding box's
  // half-diagonal 2 sqrt 3.
  const double p = 4 / (12 * 1.01 * 1.01), sigma = std::sqrt(p * (1 - p) / n);
  EXPECT_NEAR(double(hits) / n, p, 4 * sigma);
}

TEST(DirectionalEmitter, BadDirections) {
  EXPECT_THAT(
      test::load_error("<scene version='3.0.0'><emitter type='directional'><vector name='direction' "
                       "value='0, 0, 0'/></emitter></scene>"),
      testing::HasSubstr("parameter 'direction' of emitter 'directional': must give a nonzero finite direction"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><emitter type='directional'><vector name='direction' "
                               "value='0, 0, 1'/><transform name='to_world'><rotate x='1' angle='3'/></transform>"
                               "</emitter></scene>"),
              testing::HasSubstr("give either direction or to_world, not both"));
}

TEST(ConstantEmitter, IlluminatesFromEveryDirection) {
  const auto scene = light_scene(
      "<emitter type='constant'><rgb name='radiance' value='0.5'/></emitter>"
      "<shape type='sphere'/>");
  const Emitter& light = *scene->emitters().front();
  const auto ls = light.sample_Li({{0, 0, 5}, {}, {}}, {0.2f, 0.7f});
  ASSERT_TRUE(ls);
  EXPECT_TRUE(ls->is_infinite);
  EXPECT_FLOAT_EQ(ls->pdf, 1 / (4 * kPi));
  EXPECT_FLOAT_EQ(light.Le_infinite({1, 0, 0}, 0).g, 0.5f);
  // Emitted rays start outside the scene and head into it.
  const auto le = light.sample_Le({0.3f, 0.6f}, {0.9f, 0.1f});
  ASSERT_TRUE(le);
  EXPECT_GT(length(le->ray.o), 1.0f);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
