// The rate of convergence: an unbiased estimator's mean squared error
// against the exact answer falls as 1 / n with the samples per pixel n, so
// ln MSE against ln n has slope -1. A bias flattens the slope; samples that
// repeat or follow each other change it.
//
// The scene: a diffuse sphere of albedo 0.5 filling the view under a
// uniform sky of radiance 1. A convex surface never sees itself, so every
// pixel's radiance is exactly 0.5, yet every integrator has variance (sky
// samples below the horizon, light paths that miss). MSE at n = 2, 8, 32,
// 128 (independent seeds) is the mean over 1024 pixels of the squared
// error, with its standard error from the pixels' spread; the slope is
// fitted by weighted least squares and must lie within its confidence
// interval of -1 at 1%, Sidak-corrected over the integrators. The scene's
// sampler is independent unless a test names another.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tests/support/chi2.h"
#include "tests/support/test_scenes.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

std::string sphere_under_sky(const std::string& integrator, const std::string& sampler) {
  return "<scene version='3.0.0'><integrator type='" + integrator +
         "'/><sensor type='perspective'><float name='fov' value='20'/><sampler type='" + sampler +
         "'/>"
         "<transform name='to_world'><lookat origin='0, 0, 3' target='0, 0, 0' up='0, 1, 0'/></transform>"
         "<film type='hdrfilm'><integer name='width' value='32'/><integer name='height' value='32'/>"
         "<rfilter type='box'/></film></sensor>"
         "<shape type='sphere'><float name='radius' value='1'/><bsdf type='diffuse'>"
         "<rgb name='reflectance' value='0.5'/></bsdf></shape>"
         "<emitter type='constant'><rgb name='radiance' value='1'/></emitter></scene>";
}

struct Fit {
  double slope, standard_error;
  std::string trace;
};

Fit error_rate(const std::string& integrator, uint64_t seed, const std::string& sampler = "independent") {
  const auto scene = test::scene_from_xml(sphere_under_sky(integrator, sampler));
  constexpr double kExpected = 0.5;
  double sw = 0, swx = 0, swy = 0, swxx = 0, swxy = 0;
  std::string trace;
  for (const uint32_t n : {2u, 8u, 32u, 128u}) {
    const auto img = test::render_scene(scene, n, seed + n).resolve();
    const size_t pixels = img.size() / 3;
    double sum = 0, sum2 = 0;
    for (size_t p = 0; p < pixels; ++p) {
      const double e = img[3 * p + 1] - kExpected;
      sum += e * e;
      sum2 += e * e * e * e;
    }
    const double mse = sum / pixels, se = std::sqrt((sum2 / pixels - mse * mse) / (pixels - 1));
    const double x = std::log(double(n)), y = std::log(mse), w = (mse * mse) / (se * se);
    sw += w, swx += w * x, swy += w * y, swxx += w * x * x, swxy += w * x * y;
    trace += " n=" + std::to_string(n) + ": " + std::to_string(mse) + " +- " + std::to_string(se);
  }
  const double det = sw * swxx - swx * swx;
  return {(sw * swxy - swx * swy) / det, std::sqrt(sw / det), trace};
}

TEST(ConvergenceRate, MeanSquaredErrorFallsAsOneOverTheSampleCount) {
  const char* const integrators[] = {"path", "direct", "ptracer", "bdpt"};
  const double z = test::two_sided_z_critical(test::sidak_alpha(0.01, int(std::size(integrators))));
  uint64_t seed = 1000;
  for (const char* integrator : integrators) {
    const Fit fit = error_rate(integrator, seed += 1000);
    EXPECT_LT(std::abs(fit.slope + 1), z * fit.standard_error)
        << integrator << ": slope " << fit.slope << " +- " << fit.standard_error << ";" << fit.trace;
    // Precise enough that a slope of -0.8 or -1.2 fails.
    EXPECT_LT(z * fit.standard_error, 0.2) << integrator << fit.trace;
  }
}

// With ldsampler every pair of dimensions a pixel's samples draw is
// stratified, and the error of path, direct and bdpt falls faster than 1 / n
// (measured: slopes -1.75, -1.75, -1.22); the slope must lie below -1 by
// more than its confidence interval. ptracer's light paths are keyed by
// pixel but splat anywhere, so its pixels gain nothing: its slope stays -1.
TEST(ConvergenceRate, LowDiscrepancySamplesConvergeFaster) {
  const char* const integrators[] = {"path", "direct", "ptracer", "bdpt"};
  const double z = test::two_sided_z_critical(test::sidak_alpha(0.01, int(std::size(integrators))));
  uint64_t seed = 7000;
  for (const char* integrator : integrators) {
    const Fit fit = error_rate(integrator, seed += 1000, "ldsampler");
    if (std::string(integrator) == "ptracer") {
      EXPECT_LT(std::abs(fit.slope + 1), z * fit.standard_error) << integrator << ": slope " << fit.slope << fit.trace;
    } else {
      EXPECT_LT(fit.slope + 1, -z * fit.standard_error)
          << integrator << ": slope " << fit.slope << " +- " << fit.standard_error << ";" << fit.trace;
    }
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
