// The light tree against probabilities written out here. For point lights
// (no extent, every direction) the importance of a subtree of one light is
// its power times the receiver's |cos| over the squared distance, so two
// lights split the choice in the ratio of those numbers, computed in the
// test. For many lights: the probabilities of all lights sum to one at
// every point where each can light it, sample() draws each light as often
// as pmf() says (chi-square at 1%) and reports the same probability, and a
// light that can light a
// point never has probability zero there (a spot's cone is the only place
// the tree may rule a light out, and only outside it).

#include "core/lights/light_tree.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/lights/light_selection.h"
#include "core/math/constants.h"
#include "tests/support/chi2.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

LightBounds point_light(Vec3 p, float phi) {
  LightBounds b;
  b.bounds.expand(p);
  b.phi = phi;
  return b;
}

LightBounds sphere_light(Vec3 c, float r, float phi) {
  LightBounds b;
  b.bounds.expand(c - Vec3{r, r, r});
  b.bounds.expand(c + Vec3{r, r, r});
  b.phi = phi;
  return b;
}

LightBounds spot_light(Vec3 p, Vec3 axis, float cos_cutoff, float phi) {
  LightBounds b = point_light(p, phi);
  b.axis = normalize(axis);
  b.cos_theta_o = cos_cutoff;
  b.cos_theta_e = 1;
  return b;
}

TEST(LightTree, TwoPointLightsSplitByPowerCosineOverSquaredDistance) {
  const Vec3 a{0, 3, 0}, b{4, 1, 0};
  const LightTree tree({point_light(a, 10), point_light(b, 2)});
  const Vec3 p{1, 0, 0.5f}, n = normalize(Vec3{0.2f, 1, 0});
  const auto weight = [&](Vec3 q, double phi) {
    const Vec3 d = q - p;
    const double d2 = double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z;
    return phi * std::abs(double(n.x) * d.x + double(n.y) * d.y + double(n.z) * d.z) / std::sqrt(d2) / d2;
  };
  const double wa = weight(a, 10), wb = weight(b, 2);
  EXPECT_NEAR(tree.pmf(0, p, n), wa / (wa + wb), 1e-5);
  EXPECT_NEAR(tree.pmf(1, p, n), wb / (wa + wb), 1e-5);
  // In a medium (no normal) the cosine drops out.
  const auto plain = [&](Vec3 q, double phi) {
    const Vec3 d = q - p;
    return phi / (double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z);
  };
  EXPECT_NEAR(tree.pmf(0, p, {}), plain(a, 10) / (plain(a, 10) + plain(b, 2)), 1e-5);
}

TEST(LightTree, DarkLightsAreLeftOut) {
  const LightTree tree({point_light({0, 1, 0}, 0), point_light({1, 1, 0}, 3)});
  EXPECT_EQ(tree.pmf(0, {0, 0, 0}, {0, 1, 0}), 0.0f);
  EXPECT_FLOAT_EQ(tree.pmf(1, {0, 0, 0}, {0, 1, 0}), 1.0f);
  EXPECT_TRUE(LightTree({point_light({0, 1, 0}, 0)}).empty());
}

std::vector<LightBounds> random_lights(std::mt19937& rng, int count, bool spots = true) {
  std::uniform_real_distribution<float> pos(-10, 10), power(0.01f, 100), radius(0.01f, 0.5f), unit(-1, 1);
  std::vector<LightBounds> lights;
  for (int i = 0; i < count; ++i) {
    const Vec3 p{pos(rng), pos(rng), pos(rng)};
    switch (i % (spots ? 3 : 2)) {
      case 0:
        lights.push_back(point_light(p, power(rng)));
        break;
      case 1:
        lights.push_back(sphere_light(p, radius(rng), power(rng)));
        break;
      default:
        lights.push_back(spot_light(p, {unit(rng), unit(rng), unit(rng) + 1.5f}, 0.7f + 0.25f * unit(rng), power(rng)));
    }
  }
  return lights;
}

// Without spots every light can light every point, and the choice always
// finds one.
TEST(LightTree, ProbabilitiesSumToOneAndMatchTheDraws) {
  std::mt19937 rng(7);
  const auto lights = random_lights(rng, 150, false);
  const LightTree tree(lights);
  std::uniform_real_distribution<float> pos(-12, 12), u(0, kOneMinusEpsilon);
  for (int k = 0; k < 40; ++k) {
    const Vec3 p{pos(rng), pos(rng), pos(rng)};
    const Vec3 n = k % 4 == 0 ? Vec3{} : normalize(Vec3{pos(rng), pos(rng), pos(rng)});
    double sum = 0;
    for (uint32_t i = 0; i < lights.size(); ++i) sum += tree.pmf(i, p, n);
    EXPECT_NEAR(sum, 1.0, 1e-4) << "point " << k;
    for (int j = 0; j < 50; ++j) {
      float v = u(rng);
      const auto choice = tree.sample(v, p, n);
      ASSERT_TRUE(choice);
      EXPECT_EQ(choice->pmf, tree.pmf(choice->light, p, n));
      EXPECT_GE(v, 0.0f);
      EXPECT_LT(v, 1.0f);
    }
  }
}

// With spots, a subtree whose merged cone reaches a point may hold no
// light whose own cone does: a draw that ends there finds no light (and
// lights nothing, which is what those lights would have done). The draws,
// "none" among them, fall as pmf() says.
TEST(LightTree, DrawsFallAsPmfSaysWithSpots) {
  std::mt19937 rng(7);
  const auto lights = random_lights(rng, 150);
  const LightTree tree(lights);
  std::uniform_real_distribution<float> u(0, kOneMinusEpsilon);
  for (const Vec3 p : {Vec3{1, -2, 3}, Vec3{-8, 9, 0.5f}}) {
    const Vec3 n = normalize(Vec3{1, 1, 0});
    std::vector<double> counts(lights.size() + 1, 0), expected(lights.size() + 1);
    const int draws = 400000;
    for (int j = 0; j < draws; ++j) {
      float v = u(rng);
      const auto choice = tree.sample(v, p, n);
      counts[choice ? choice->light : lights.size()] += 1;
      if (choice) {
        EXPECT_EQ(choice->pmf, tree.pmf(choice->light, p, n));
      }
    }
    double sum = 0;
    for (uint32_t i = 0; i < lights.size(); ++i) {
      expected[i] = tree.pmf(i, p, n) * draws;
      sum += tree.pmf(i, p, n);
    }
    EXPECT_LE(sum, 1 + 1e-4);
    expected[lights.size()] = std::max(0.0, 1 - sum) * draws;
    const auto chi2 = test::chi2_test_counts(counts, expected);
    EXPECT_GT(chi2.p_value, 0.01) << chi2.report;
  }
}

TEST(LightTree, OnlyASpotsConeRulesItOut) {
  std::mt19937 rng(11);
  const auto lights = random_lights(rng, 60);
  const LightTree tree(lights);
  std::uniform_real_distribution<float> pos(-12, 12);
  int ruled_out = 0;
  for (int k = 0; k < 2000; ++k) {
    const Vec3 p{pos(rng), pos(rng), pos(rng)};
    const Vec3 n = normalize(Vec3{pos(rng), pos(rng), pos(rng)});
    for (uint32_t i = 0; i < lights.size(); ++i) {
      const LightBounds& l = lights[i];
      const Vec3 to_p = normalize(p - l.bounds.center());
      const bool lit = l.cos_theta_o <= -1 || dot(to_p, l.axis) > l.cos_theta_o;
      if (lit) {
        EXPECT_GT(tree.pmf(i, p, n), 0.0f) << "light " << i << " at point " << k;
      } else if (dot(to_p, l.axis) < l.cos_theta_o - 0.01f) {
        EXPECT_EQ(tree.pmf(i, p, n), 0.0f) << "spot " << i << " lights point " << k << " from outside its cone";
        ++ruled_out;
      }
    }
  }
  EXPECT_GT(ruled_out, 1000);
}

TEST(LightBounds, MergedConeHoldsBothCones) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(-1, 1), cosine(-0.2f, 0.99f);
  for (int k = 0; k < 500; ++k) {
    LightBounds a = spot_light({}, {unit(rng), unit(rng), unit(rng) + 0.01f}, cosine(rng), 1);
    LightBounds b = spot_light({}, {unit(rng), unit(rng), unit(rng) + 0.01f}, cosine(rng), 1);
    const LightBounds m = LightBounds::merge(a, b);
    EXPECT_FLOAT_EQ(m.phi, 2);
    if (m.cos_theta_o <= -1) continue;
    // Each cone's rim, sampled, lies within the merged cone.
    for (const LightBounds* c : {&a, &b}) {
      const Vec3 t = normalize(std::abs(c->axis.x) < 0.9f ? cross(c->axis, {1, 0, 0}) : cross(c->axis, {0, 1, 0}));
      const Vec3 s = cross(c->axis, t);
      const float sin_o = std::sqrt(1 - c->cos_theta_o * c->cos_theta_o);
      for (int j = 0; j < 32; ++j) {
        const float phi = 2 * kPi * float(j) / 32;
        const Vec3 rim = c->axis * c->cos_theta_o + (t * std::cos(phi) + s * std::sin(phi)) * sin_o;
        EXPECT_GE(dot(rim, m.axis), m.cos_theta_o - 1e-4f) << "pair " << k;
      }
    }
  }
}

// Rectangles and disks light only the half-space their normal faces, and
// the tree knows it: above two panels facing down, only the sphere light
// is chosen; below them, all three are. A cube has no single normal.
TEST(LightSelection, FlatLightsAreNotChosenFromBehind) {
  const auto panel = [](const std::string& type, float x) {
    return "<shape type='" + type +
           "'><transform name='to_world'><scale value='0.5'/><rotate x='1' angle='90'/>"
           "<translate x='" +
           std::to_string(x) +
           "' y='2'/></transform><emitter type='area'><rgb name='radiance' "
           "value='5'/></emitter></shape>";
  };
  const auto scene = test::scene_from_xml(
      "<scene version='3.0.0'>" + panel("rectangle", 0) + panel("disk", 3) +
      "<shape type='sphere'><point name='center' x='-3' y='2' z='0'/><float name='radius' value='0.2'/>"
      "<emitter type='area'><rgb name='radiance' value='4'/></emitter></shape></scene>");
  const LightSelection& selection = scene->light_selection();
  for (const auto& s : scene->shapes()) EXPECT_EQ(s->flat_normal().has_value(), s->kind() != "sphere") << s->kind();
  const ReferencePoint above{{1, 4, 0}, {}, {0, 1, 0}, 0}, below{{1, 0, 0}, {}, {0, 1, 0}, 0};
  for (const auto& e : scene->emitters()) {
    const bool sphere = e->light_bounds()->cos_theta_o <= -1;
    EXPECT_EQ(selection.pmf(e.get(), above) > 0, sphere);
    EXPECT_GT(selection.pmf(e.get(), below), 0);
  }
  const auto cube = test::scene_from_xml("<scene version='3.0.0'><shape type='cube'/></scene>");
  EXPECT_FALSE(cube->shapes().front()->flat_normal());
}

// Through the scene: an environment and a directional light (which the
// tree cannot bound) share 2/3 of the choice by power, the area and point
// lights the rest through the tree.
TEST(LightSelection, TreeAndUnboundedLightsShareTheChoice) {
  const auto scene = test::scene_from_xml(
      "<scene version='3.0.0'>"
      "<emitter type='constant'><rgb name='radiance' value='0.5'/></emitter>"
      "<emitter type='directional'><vector name='direction' x='0' y='-1' z='0'/><rgb name='irradiance' "
      "value='2'/></emitter>"
      "<emitter type='point'><point name='position' x='0' y='3' z='0'/><rgb name='intensity' value='5'/></emitter>"
      "<emitter type='point'><point name='position' x='6' y='3' z='0'/><rgb name='intensity' value='5'/></emitter>"
      "<shape type='sphere'><point name='center' x='-3' y='2' z='1'/><float name='radius' value='0.2'/>"
      "<emitter type='area'><rgb name='radiance' value='4'/></emitter></shape>"
      "</scene>");
  const LightSelection& selection = scene->light_selection();
  EXPECT_EQ(selection.tree_lights(), 3u);
  const ReferencePoint ref{{1, 0, 0}, {}, {0, 1, 0}, 0};
  double unbounded = 0, total = 0;
  for (const auto& e : scene->emitters()) {
    const float p = selection.pmf(e.get(), ref);
    total += p;
    if (!e->light_bounds()) unbounded += p;
  }
  EXPECT_NEAR(total, 1.0, 1e-6);
  EXPECT_NEAR(unbounded, 2.0 / 3.0, 1e-6);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0, kOneMinusEpsilon);
  for (int j = 0; j < 1000; ++j) {
    float v = u(rng);
    const auto choice = selection.sample(v, ref);
    ASSERT_TRUE(choice);
    EXPECT_EQ(choice->pmf, selection.pmf(choice->emitter, ref));
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
