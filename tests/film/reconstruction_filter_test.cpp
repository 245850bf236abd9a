#include "core/film/reconstruction_filter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/registry/properties.h"
#include "tests/support/chi2.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

std::shared_ptr<ReconstructionFilter> make_filter(const std::string& name) {
  const PluginInfo* info = Registry::instance().find("rfilter", name);
  return std::dynamic_pointer_cast<ReconstructionFilter>(info->create(Properties(*info, {"test", 1})));
}

double integral_1d(const ReconstructionFilter& f) {
  const int n = 100000;
  double sum = 0;
  for (int i = 0; i < n; ++i) sum += f.eval(-f.radius() + (i + 0.5f) * 2 * f.radius() / n);
  return sum * 2 * f.radius() / n;
}

class Filter : public testing::TestWithParam<std::string> {};

// Filter importance sampling: offsets are distributed as |f| normalised, and
// the weights f / pdf average to the filter's integral, so the weighted
// average the film forms is normalised.
TEST_P(Filter, WeightsNormaliseAndSamplesFollowTheFilter) {
  const auto filter = make_filter(GetParam());
  const double norm = integral_1d(*filter);
  test::UniformSource u(3);
  double weight_sum = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const FilterSample s = filter->sample(u.next_2d());
    EXPECT_LE(std::abs(s.offset.x), filter->radius());
    EXPECT_LE(std::abs(s.offset.y), filter->radius());
    weight_sum += s.weight;
  }
  EXPECT_NEAR(weight_sum / n, norm * norm, 2e-3 * norm * norm);

  const float r = filter->radius();
  const auto result = test::chi2_test_rect(
      [&](test::UniformSource& src) -> std::optional<Vec2> { return filter->sample(src.next_2d()).offset; },
      [&](const Vec2& p) { return filter->eval(p.x) * filter->eval(p.y) / (norm * norm); }, {-r, r, -r, r},
      {.sample_count = 400000, .bins_u = 20, .bins_v = 20, .seed = 5});
  // 1% significance, Sidak-corrected over the three filters.
  EXPECT_GT(result.p_value, test::sidak_alpha(0.01, 3)) << result.report;
}

// Sampling inverts the CDF of |f|: the offset drawn for u has a fraction u
// of the filter's mass below it (integrated here by the midpoint rule, not
// from the sampler's tables), and grows with u, also across the cells a
// sample's search starts from.
TEST_P(Filter, OffsetsInvertTheCdf) {
  const auto filter = make_filter(GetParam());
  const float r = filter->radius();
  const int steps = 200000;
  std::vector<double> cdf(steps + 1, 0);
  for (int i = 0; i < steps; ++i) cdf[i + 1] = cdf[i] + std::abs(filter->eval(-r + (i + 0.5f) * 2 * r / steps));
  const auto mass_below = [&](float x) {
    const double t = std::clamp((double(x) + r) / (2 * r) * steps, 0.0, double(steps));
    const int i = std::min(int(t), steps - 1);
    return (cdf[i] + (t - i) * (cdf[i + 1] - cdf[i])) / cdf[steps];
  };
  std::vector<float> us;
  for (int i = 0; i < 4096; ++i) us.push_back((i + 0.5f) / 4096);
  for (int g = 1; g < 256; ++g)
    for (float u : {float(g) / 256, std::nextafter(float(g) / 256, 0.0f)}) us.push_back(u);
  std::sort(us.begin(), us.end());
  float previous = -r;
  for (float u : us) {
    const float x = filter->sample({u, 0.5f}).offset.x;
    EXPECT_NEAR(mass_below(x), u, 2e-3) << "u = " << u;
    EXPECT_GE(x, previous) << "u = " << u;
    previous = x;
  }
}

INSTANTIATE_TEST_SUITE_P(AllFilters, Filter, testing::Values("box", "tent", "gaussian"));

TEST(Filter, DefaultRadii) {
  EXPECT_FLOAT_EQ(make_filter("box")->radius(), 0.5f);
  EXPECT_FLOAT_EQ(make_filter("tent")->radius(), 1.0f);
  EXPECT_FLOAT_EQ(make_filter("gaussian")->radius(), 2.0f);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
