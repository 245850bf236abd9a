// The bias of `photon` after N rounds, measured against the value the
// Knaus-Zwicker schedule predicts for it, on a caustic known in closed form.
//
// A point light of intensity I at (a, 0, h) stands beside a perfect mirror
// filling the plane x = 0 (facing +x) above a diffuse floor (albedo rho) at
// z = 0, x > 0. The floor's irradiance is the light's, I h / d^3, plus the
// caustic of its mirror image at (-a, 0, h), I h / d'^3. Light the floor
// sends to the mirror climbs away from the floor, so nothing else arrives.
// `path` renders the direct part exactly (next-event estimation); the
// caustic part comes from the photon map, whose estimate with radius r has
// the mean of the caustic irradiance over the disk of radius r (a photon
// density estimate with a uniform kernel), times rho / pi. With one sample
// per pixel per round, N rounds average the disks of radii r_0 .. r_{N-1},
// r_i^2 = r_0^2 prod_{k=1}^{i} (k + alpha) / (k + 1): a bias that falls as
// the mean of r_i^2, N^-(1 - alpha), since the disk's excess over its
// centre grows as r^2.
//
// An orthographic camera sees floor points 0.2 to 0.3 from the mirror, where
// the caustic is strongly curved. The expected image is integrated here
// (pixels by the midpoint rule, disks by Gauss-Legendre in the radius and
// the midpoint rule in the angle), the caustic written from the geometry,
// not from the renderer. The mean of independent runs at 1, 4, 16 and 64
// rounds must equal the predicted biased value (1 %, Sidak-corrected,
// Student's t) and, to show the test can see a wrong schedule, lie outside
// twice that interval around the unbiased value. At 64 rounds the bias is
// 1.8 % of the image (0.036) and a run's standard deviation 0.0075. Seeds
// are fixed.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "tests/support/chi2.h"
#include "tests/support/independent_runs.h"
#include "tests/support/test_scenes.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {

constexpr double kA = 0.02, kH = 0.15, kRho = 0.5, kIntensity = 1;
constexpr double kRadius = 0.2, kAlpha = 0.3;
constexpr double kCentreX = 0.25, kHalf = 0.05;  // the view: x in [0.2, 0.3], y in [-0.05, 0.05]
constexpr int kPixels = 8, kRuns = 12;

std::string scene_xml() {
  return "<scene version='3.0.0'><integrator type='photon'><integer name='photons' value='20000'/>"
         "<float name='radius' value='" +
         std::to_string(kRadius) + "'/><float name='alpha' value='" + std::to_string(kAlpha) +
         "'/></integrator>"
         "<sensor type='orthographic'><transform name='to_world'><scale x='" +
         std::to_string(kHalf) + "' y='" + std::to_string(kHalf) + "'/><lookat origin='" + std::to_string(kCentreX) +
         ", 0, 1' target='" + std::to_string(kCentreX) +
         ", 0, 0' up='0, 1, 0'/></transform>"
         "<film type='hdrfilm'><integer name='width' value='8'/><integer name='height' value='8'/>"
         "<rfilter type='box'/></film></sensor>"
         "<shape type='rectangle'><transform name='to_world'><translate x='1'/></transform>"
         "<bsdf type='diffuse'><rgb name='reflectance' value='" +
         std::to_string(kRho) +
         "'/></bsdf></shape>"
         "<shape type='rectangle'><transform name='to_world'><rotate y='1' angle='90'/><translate z='1'/>"
         "</transform><bsdf type='conductor'/></shape>"
         "<emitter type='point'><point name='position' x='" +
         std::to_string(kA) + "' y='0' z='" + std::to_string(kH) + "'/><rgb name='intensity' value='" +
         std::to_string(kIntensity) + "'/></emitter></scene>";
}

// Irradiance on the floor at (x, y) from a point source at height kH whose
// foot is (fx, 0).
double irradiance(double x, double y, double fx) {
  const double d2 = (x - fx) * (x - fx) + y * y + kH * kH;
  return kIntensity * kH / (d2 * std::sqrt(d2));
}

// The caustic irradiance averaged over the disk of radius r around (x, y):
// 16 Gauss-Legendre nodes in the radius (weighted by it), 48 angles.
double disk_mean_caustic(double x, double y, double r) {
  static const double node[8] = {0.0950125098376374, 0.2816035507792589, 0.4580167776572274, 0.6178762444026438,
                                 0.7554044083550030, 0.8656312023878318, 0.9445750230732326, 0.9894009349916499};
  static const double weight[8] = {0.1894506104550685, 0.1826034150449236, 0.1691565193950025, 0.1495959888165767,
                                   0.1246289712555339, 0.0951585116824928, 0.0622535239386479, 0.0271524594117541};
  constexpr int kAngles = 48;
  double sum = 0;
  for (int k = 0; k < 16; ++k) {
    const double t = k < 8 ? -node[7 - k] : node[k - 8], w = k < 8 ? weight[7 - k] : weight[k - 8];
    const double rho = 0.5 * r * (t + 1);
    double ring = 0;
    for (int j = 0; j < kAngles; ++j) {
      const double phi = 2 * M_PI * (j + 0.5) / kAngles;
      ring += irradiance(x + rho * std::cos(phi), y + rho * std::sin(phi), -kA);
    }
    sum += w * 0.5 * r * rho * ring * 2 * M_PI / kAngles;
  }
  return sum / (M_PI * r * r);
}

// The radius of every round, from the schedule's definition.
std::vector<double> round_radii(int rounds) {
  std::vector<double> r;
  double r2 = kRadius * kRadius;
  for (int i = 0; i < rounds; ++i) {
    if (i > 0) r2 *= (i + kAlpha) / (i + 1);
    r.push_back(std::sqrt(r2));
  }
  return r;
}

// The image's mean: pixels by the midpoint rule over 4x4 points each
// (image right is +x, image down is -y); `rounds` 0 for the unbiased value.
double expected_mean(int rounds) {
  const auto radii = round_radii(rounds);
  constexpr int n = kPixels * 4;
  double sum = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = kCentreX + kHalf * (2 * (i + 0.5) / n - 1), y = -kHalf * (2 * (j + 0.5) / n - 1);
      double caustic = 0;
      if (rounds == 0) caustic = irradiance(x, y, -kA);
      for (double r : radii) caustic += disk_mean_caustic(x, y, r) / rounds;
      sum += kRho / M_PI * (irradiance(x, y, kA) + caustic);
    }
  return sum / (n * n);
}

TEST(PhotonBias, FallsWithTheRoundsAsTheRadiusSchedulePredicts) {
  const auto scene = test::scene_from_xml(scene_xml());
  const std::vector<test::Region> whole{{{0, 0}, {kPixels, kPixels}}};
  const int rounds[] = {1, 4, 16, 64};
  const double t_critical = test::two_sided_t_critical(test::sidak_alpha(0.01, int(std::size(rounds))), kRuns - 1);
  const double unbiased = expected_mean(0);
  uint64_t seed = 1;
  for (int n : rounds) {
    uint64_t non_finite = 0;
    const test::RegionEstimate e =
        test::estimate_regions(scene, whole, uint32_t(n), kRuns, seed += kRuns, &non_finite)[0];
    EXPECT_EQ(non_finite, 0u);
    const double predicted = expected_mean(n);
    EXPECT_LT(std::abs(e.mean - predicted), t_critical * e.standard_error)
        << n << " rounds: " << e.mean << " +- " << e.standard_error << ", predicted " << predicted << " (bias "
        << predicted - unbiased << "), unbiased " << unbiased;
    EXPECT_GT(std::abs(e.mean - unbiased), 2 * t_critical * e.standard_error)
        << n << " rounds: the bias " << e.mean - unbiased << " is too small to tell a schedule from another";
  }
}

}  // namespace
}  // namespace caustica
