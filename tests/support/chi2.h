#pragma once

// Chi-square goodness-of-fit testing of sampling routines against their pdfs.
//
// A sampler is run N times and its results histogrammed; each bin's expected
// count is N times the pdf integrated numerically over the bin. Directions are
// binned over (cos theta, phi) in [-1,1] x [0,2pi), where solid angle is
// d(cos theta) d(phi), so a solid-angle pdf integrates there without a
// Jacobian. Failed or invalid samples form their own category, expected to hold
// N times the probability mass the pdf leaves out, so a sampler that fails more
// (or less) often than its pdf admits is caught as well.

#include <cstdint>
#include <functional>
#include <optional>
#include <random>
#include <span>
#include <string>

#include "core/math/vec.h"

namespace caustica::test {

// Reproducible uniform numbers in [0,1) for the sampler under test.
class UniformSource {
 public:
  explicit UniformSource(uint32_t seed) : rng_(seed) {}

  float next_1d();
  Vec2 next_2d();

 private:
  std::mt19937 rng_;
  std::uniform_real_distribution<float> dist_{0.0f, 1.0f};
};

// A sampler returns nullopt when it fails to produce a sample.
using DirectionSampler = std::function<std::optional<Vec3>(UniformSource&)>;
// Density with respect to solid angle at a unit direction.
using DirectionPdf = std::function<double(const Vec3&)>;
using PointSampler = std::function<std::optional<Vec2>(UniformSource&)>;
// Density with respect to area at a point of the rectangle.
using PointPdf = std::function<double(const Vec2&)>;

// A closed rectangle [x0,x1] x [y0,y1].
struct Rect {
  double x0 = 0, x1 = 1, y0 = 0, y1 = 1;
};

struct Chi2Options {
  int sample_count = 1'000'000;
  // Histogram resolution along cos(theta) and phi for directions, along x and
  // y for points.
  int bins_u = 40;
  int bins_v = 80;
  uint32_t seed = 1;
  // Bins expecting fewer samples than this are pooled, as the chi-square
  // approximation of the statistic's distribution breaks down for them.
  double min_expected = 5;
};

struct Chi2Result {
  double statistic = 0;
  int dof = 0;
  double p_value = 0;
  // Summary and the bins contributing most to the statistic, for failures.
  std::string report;
};

Chi2Result chi2_test_sphere(const DirectionSampler& sample, const DirectionPdf& pdf, const Chi2Options& options = {});
Chi2Result chi2_test_rect(const PointSampler& sample, const PointPdf& pdf, const Rect& domain,
                          const Chi2Options& options = {});
// Observed against expected counts per category, e.g. for discrete sampling.
// Any sample in a category expected to be empty fails the test outright.
Chi2Result chi2_test_counts(std::span<const double> observed, std::span<const double> expected,
                            double min_expected = 5);

// Probability that a chi-square variable with dof degrees of freedom is at
// least statistic: the regularized upper incomplete gamma Q(dof/2, statistic/2).
double chi2_p_value(double statistic, int dof);

// Per-test significance that keeps the chance of any false failure among
// num_tests independent tests at alpha.
double sidak_alpha(double alpha, int num_tests);

// Adaptive numerical integrals over the whole sphere and over a rectangle,
// for checking that pdfs are normalised.
double integrate_sphere(const DirectionPdf& pdf, int bins_cos_theta = 40, int bins_phi = 80);
double integrate_rect(const PointPdf& pdf, const Rect& domain, int bins_x = 32, int bins_y = 32);

}  // namespace caustica::test
