#include "core/sampling/piecewise_constant_2d.h"

#include <gtest/gtest.h>

#include <vector>

#include "tests/support/chi2.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// Cells are chosen in proportion to their weights (chi-square at 0.1%),
// never where the weight is zero, and the density is weight / mean weight.
TEST(PiecewiseConstant2D, SamplesCellsByWeight) {
  const int w = 5, h = 4;
  const std::vector<float> weights = {1, 2, 0, 4, 1,  //
                                      0, 0, 0, 0, 0,  //
                                      3, 1, 1, 0, 2,  //
                                      5, 0, 1, 1, 1};
  const PiecewiseConstant2D d(weights, w, h);
  double total = 0;
  for (float x : weights) total += x;
  std::vector<double> observed(weights.size(), 0), expected(weights.size());
  const int n = 200000;
  for (size_t i = 0; i < weights.size(); ++i) expected[i] = n * weights[i] / total;
  test::UniformSource u(11);
  for (int i = 0; i < n; ++i) {
    float pdf = 0;
    const Vec2 p = d.sample(u.next_2d(), &pdf);
    ASSERT_GE(p.x, 0);
    ASSERT_LT(p.x, 1);
    ASSERT_GE(p.y, 0);
    ASSERT_LT(p.y, 1);
    const size_t cell = size_t(int(p.y * h)) * w + size_t(int(p.x * w));
    observed[cell] += 1;
    EXPECT_FLOAT_EQ(pdf, float(weights[cell] / (total / (w * h))));
    EXPECT_FLOAT_EQ(d.pdf(p), pdf);
  }
  const auto chi2 = test::chi2_test_counts(observed, expected);
  EXPECT_GT(chi2.p_value, 0.001) << chi2.report;
  EXPECT_EQ(d.pdf({0.5f, 0.3f}), 0);  // the empty row
}

TEST(PiecewiseConstant2D, AllZeroWeightsAreRefused) {
  const std::vector<float> zeros(6, 0.0f);
  EXPECT_THROW(PiecewiseConstant2D(zeros, 3, 2), std::invalid_argument);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
