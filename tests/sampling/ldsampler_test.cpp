// ldsampler's stratification. Every aligned block of 2^m sample indices of a
// pixel (so a render of sample range [k 2^m, (k + 1) 2^m) too) puts one
// value in each interval of length 2^-m of every 1-D dimension, and one
// point in each elementary interval of area 2^-m (2^a by 2^(m - a) cells,
// every a) of every 2-D pair. Dimensions of different pairs project
// uniformly (chi-square at 1 %, Sidak-corrected), and a smooth integrand's
// error falls far below the independent sampler's while its mean stays
// unbiased. Seeds are fixed.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/sampling/sampler.h"
#include "tests/support/chi2.h"
#include "tests/support/samplers.h"
#include "tests/support/test_scenes.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// One sample's draws in the order a path might make them: 1-D, 2-D, 1-D, 2-D, 1-D, 2-D.
struct Draws {
  float d1[3];
  Vec2 d2[3];
};

Draws draw(Sampler& s, SampleKey key, uint64_t index, uint64_t seed) {
  s.start_sample(key, index, seed);
  Draws d;
  for (int k = 0; k < 3; ++k) {
    d.d1[k] = s.next_1d();
    d.d2[k] = s.next_2d();
  }
  return d;
}

TEST(LowDiscrepancySampler, EveryAlignedBlockIsAnElementaryNet) {
  auto s = test::make_sampler("ldsampler", {{"seed", 3}});
  for (const SampleKey key : {SampleKey::camera({0, 0}), SampleKey::camera({5, 9}), SampleKey::light_path({5, 9}),
                              SampleKey::photon_round(7)})
    for (const int m : {4, 7, 10}) {
      const uint64_t n = uint64_t(1) << m;
      for (const uint64_t first : {uint64_t(0), 3 * n}) {
        std::vector<Draws> block;
        for (uint64_t i = first; i < first + n; ++i) block.push_back(draw(*s, key, i, 11));
        for (int k = 0; k < 3; ++k) {
          std::vector<int> count(n, 0);
          for (const Draws& d : block) ++count[size_t(d.d1[k] * float(n))];
          for (uint64_t c = 0; c < n; ++c)
            ASSERT_EQ(count[c], 1) << "1-D dimension " << k << ", m " << m << ", first " << first << ", cell " << c;
          for (int a = 0; a <= m; ++a) {
            const uint64_t nx = uint64_t(1) << a, ny = n / nx;
            std::vector<int> cells(n, 0);
            for (const Draws& d : block) ++cells[size_t(d.d2[k].y * float(ny)) * nx + size_t(d.d2[k].x * float(nx))];
            for (uint64_t c = 0; c < n; ++c)
              ASSERT_EQ(cells[c], 1) << "pair " << k << ", m " << m << ", first " << first << ", cells " << nx << " x "
                                     << ny << ", cell " << c;
          }
        }
      }
    }
}

// Values of different dimensions, paired across pairs, fill the square
// uniformly over many pixels: 16 x 16 bins.
TEST(LowDiscrepancySampler, ProjectionsAcrossPairsAreUniform) {
  auto s = test::make_sampler("ldsampler");
  constexpr int kBins = 16;
  const auto bin = [](float u, float v) { return size_t(int(u * kBins) * kBins + int(v * kBins)); };
  std::vector<std::vector<double>> observed(4, std::vector<double>(kBins * kBins, 0));
  for (int p = 0; p < 64 * 64; ++p)
    for (uint64_t i = 0; i < 16; ++i) {
      const Draws d = draw(*s, SampleKey::camera({p % 64, p / 64}), i, 0);
      ++observed[0][bin(d.d1[0], d.d1[1])];
      ++observed[1][bin(d.d2[0].x, d.d2[1].x)];
      ++observed[2][bin(d.d2[0].y, d.d2[2].y)];
      ++observed[3][bin(d.d1[2], d.d2[1].y)];
    }
  const double alpha = test::sidak_alpha(0.01, 4);
  for (const auto& o : observed) {
    const std::vector<double> expected(o.size(), 64.0 * 64 * 16 / (kBins * kBins));
    const auto result = test::chi2_test_counts(o, expected);
    EXPECT_GT(result.p_value, alpha) << result.report;
  }
}

// The estimate of the integral of f(x, y) = x exp(x y) over the unit square
// (e - 2) from 256 samples of one pixel, over 1024 pixels: ldsampler's mean
// agrees with the integral (z-test at 1 %) and its root-mean-square error is
// under a tenth of the independent sampler's (for an Owen-scrambled net the
// variance falls as n^-3 for smooth integrands, against n^-1).
TEST(LowDiscrepancySampler, SmoothIntegrandsConvergeFasterWithoutBias) {
  const double exact = std::exp(1.0) - 2;
  double rms[2];
  int which = 0;
  for (const char* name : {"independent", "ldsampler"}) {
    auto s = test::make_sampler(name);
    double sum = 0, sum2 = 0;
    constexpr int kPixels = 1024, kSamples = 256;
    for (int p = 0; p < kPixels; ++p) {
      double estimate = 0;
      for (int i = 0; i < kSamples; ++i) {
        s->start_sample(SampleKey::camera({p, 0}), i, 2);
        s->next_1d();
        const Vec2 u = s->next_2d();
        estimate += u.x * std::exp(double(u.x) * u.y) / kSamples;
      }
      sum += estimate - exact;
      sum2 += (estimate - exact) * (estimate - exact);
    }
    const double bias = sum / kPixels, se = std::sqrt((sum2 / kPixels - bias * bias) / (kPixels - 1));
    EXPECT_LT(std::abs(bias), test::two_sided_z_critical(0.01) * se) << name;
    rms[which++] = std::sqrt(sum2 / kPixels);
  }
  EXPECT_LT(rms[1], 0.1 * rms[0]) << "independent " << rms[0] << ", ldsampler " << rms[1];
}

TEST(LowDiscrepancySampler, BadSampleCount) {
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><sensor type='perspective'><sampler type='ldsampler'>\n"
                               "<integer name='sample_count' value='0'/></sampler></sensor></scene>"),
              testing::HasSubstr("test.xml:2: parameter 'sample_count' of sampler 'ldsampler': must be a positive "
                                 "32-bit count"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
