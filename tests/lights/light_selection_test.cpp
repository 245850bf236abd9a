// Light selection against powers written out here: six lights of unequal
// power (point lights 4 pi I, area lights pi L A) and one dark light.
// sample() must pick each light as often as its share of the total power
// (chi-square at 1%), and pmf() must give exactly the probability sample()
// uses, for the light sample() returned and for every other.

#include "core/lights/light_selection.h"

#include <gtest/gtest.h>

#include <map>
#include <random>

#include "core/math/constants.h"
#include "tests/support/chi2.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

struct LightSpec {
  std::string xml;
  double power;  // average over channels, W
};

std::vector<LightSpec> lights() {
  const auto point = [](double intensity, double x) {
    return LightSpec{"<emitter type='point'><point name='position' x='" + std::to_string(x) +
                         "' y='0' z='3'/><rgb name='intensity' value='" + std::to_string(intensity) + "'/></emitter>",
                     4 * M_PI * intensity};
  };
  // A rectangle of half-sides a and b has area 4 a b.
  const auto panel = [](double radiance, double a, double b) {
    return LightSpec{"<shape type='rectangle'><transform name='to_world'><scale x='" + std::to_string(a) + "' y='" +
                         std::to_string(b) +
                         "'/><translate z='4'/></transform><emitter type='area'><rgb "
                         "name='radiance' value='" +
                         std::to_string(radiance) + "'/></emitter></shape>",
                     M_PI * radiance * 4 * a * b};
  };
  return {point(1, 0),
          point(7, 1),
          panel(3, 0.5, 0.25),
          panel(0.6, 2, 1),
          point(0.2, -1),
          panel(10, 0.1, 0.1),
          {"<emitter type='point'><point name='position' x='2' y='0' z='3'/><rgb name='intensity' value='0'/>"
           "</emitter>",
           0}};
}

TEST(LightSelection, PicksLightsInProportionToTheirPower) {
  std::string xml = "<scene version='3.0.0'>";
  for (const LightSpec& l : lights()) xml += l.xml;
  const auto scene = test::scene_from_xml(xml + "</scene>");
  // The scene's emitters are its point lights in order, then its area
  // lights in order; match them to the specs by power.
  double total = 0;
  for (const LightSpec& l : lights()) total += l.power;
  std::map<const Emitter*, double> expected;
  for (const auto& e : scene->emitters()) {
    const double p = e->power().average();
    for (const LightSpec& l : lights())
      if (std::abs(p - l.power) <= 1e-5 * std::max(1.0, l.power)) expected[e.get()] = l.power / total;
  }
  ASSERT_EQ(expected.size(), lights().size());

  const LightSelection& selection = scene->light_selection();
  for (const auto& [emitter, probability] : expected)
    EXPECT_NEAR(selection.pmf(emitter), probability, 1e-6) << "power " << emitter->power().average();

  std::mt19937 rng(12);
  std::uniform_real_distribution<float> u(0, kOneMinusEpsilon);
  std::map<const Emitter*, double> counts;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    float v = u(rng);
    const auto choice = selection.sample(v);
    ASSERT_TRUE(choice);
    EXPECT_FLOAT_EQ(choice->pmf, selection.pmf(choice->emitter));
    EXPECT_GE(v, 0.0f);
    EXPECT_LT(v, 1.0f);
    counts[choice->emitter] += 1;
  }
  std::vector<double> observed, wanted;
  for (const auto& [emitter, probability] : expected) {
    if (probability == 0) {
      EXPECT_EQ(counts[emitter], 0);  // a dark light is never chosen
      continue;
    }
    observed.push_back(counts[emitter]);
    wanted.push_back(probability * n);
  }
  const auto chi2 = test::chi2_test_counts(observed, wanted);
  EXPECT_GT(chi2.p_value, 0.01) << chi2.report;
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
