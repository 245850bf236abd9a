// The bias of the progressive photon methods after N rounds, measured
// against the value their radius schedules predict, on a caustic known in
// closed form.
//
// A point light of intensity I at (a, 0, h) stands beside a perfect mirror
// filling the plane x = 0 (facing +x) above a diffuse floor (albedo rho) at
// z = 0, x > 0. The floor's irradiance is the light's, I h / d^3, plus the
// caustic of its mirror image at (-a, 0, h), I h / d'^3. Light the floor
// sends to the mirror climbs away from the floor, so nothing else arrives,
// and the only photons stored near the floor are caustic ones. An
// orthographic camera sees floor points 0.2 to 0.3 from the mirror, where
// the caustic is strongly curved; direct light comes from next-event
// estimation, exactly. Expected values are integrated here (pixels by the
// midpoint rule, disks by Gauss-Legendre in the radius and the midpoint rule
// in the angle) from the geometry, not from the renderer.
//
// - photon: a photon density estimate with radius r has the mean of the
//   caustic irradiance over the disk of radius r, times rho / pi. With one
//   sample per pixel per round, N rounds average the disks of radii r_0 ..
//   r_{N-1}, r_i^2 = r_0^2 prod_{k=1}^{i} (k + alpha) / (k + 1) (Knaus and
//   Zwicker 2011): a bias that falls as the mean of r_i^2, N^-(1 - alpha),
//   since the disk's excess over its centre grows as r^2. At 64 rounds the
//   bias is 1.8 % of the image (0.036) and a run's standard deviation 0.0075.
// - sppm: each pixel's radius shrinks with the photons it finds, so its
//   estimate is simulated (simulate_sppm) rather than integrated; that
//   also gives the radii's mean square, which the render reports.
//
// The means of independent runs at 1, 4, 16 and 64 rounds must equal the
// predictions (1 %, Sidak-corrected, Student's t) and, to show the tests can
// see a wrong schedule, lie outside twice that interval around the unbiased
// value (sppm: up to 16 iterations, its bias falling faster). Seeds are
// fixed.
//
// - vcm's merge-only mode: no connection can make these paths (the light is
//   a point, the camera orthographic), so every path is a merge at the
//   floor, direct light included, weighed one. With one light subpath per
//   pixel (32x32 of them, the view the same) and photon's radius schedule,
//   its mean after N iterations averages the disks of the direct and the
//   caustic irradiance alike; the same tests apply (the bias's size up to
//   16 iterations).

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "tests/support/chi2.h"
#include "tests/support/independent_runs.h"
#include "tests/support/test_scenes.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

constexpr double kA = 0.02, kH = 0.15, kRho = 0.5, kIntensity = 1;
constexpr double kRadius = 0.2, kAlpha = 0.3;
constexpr double kCentreX = 0.25, kHalf = 0.05;  // the view: x in [0.2, 0.3], y in [-0.05, 0.05]
constexpr int kPixels = 8, kRuns = 12;

// `integrator`: photon or sppm (20000 photons a round), or vcm; `pixels`
// across the film.
std::string scene_xml(const std::string& integrator, int pixels = kPixels) {
  return "<scene version='3.0.0'><integrator type='" + integrator + "'>" +
         (integrator == "vcm" ? "<string name='mode' value='merge'/>" : "<integer name='photons' value='20000'/>") +
         "<float name='radius' value='" + std::to_string(kRadius) + "'/><float name='alpha' value='" +
         std::to_string(kAlpha) +
         "'/></integrator>"
         "<sensor type='orthographic'><transform name='to_world'><scale x='" +
         std::to_string(kHalf) + "' y='" + std::to_string(kHalf) + "'/><lookat origin='" + std::to_string(kCentreX) +
         ", 0, 1' target='" + std::to_string(kCentreX) +
         ", 0, 0' up='0, 1, 0'/></transform>"
         "<film type='hdrfilm'><integer name='width' value='" +
         std::to_string(pixels) + "'/><integer name='height' value='" + std::to_string(pixels) +
         "'/>"
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

// The irradiance from the source whose foot is (fx, 0) averaged over the
// disk of radius r around (x, y): 16 Gauss-Legendre nodes in the radius
// (weighted by it), 48 angles.
double disk_mean(double x, double y, double r, double fx) {
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
      ring += irradiance(x + rho * std::cos(phi), y + rho * std::sin(phi), fx);
    }
    sum += w * 0.5 * r * rho * ring * 2 * M_PI / kAngles;
  }
  return sum / (M_PI * r * r);
}

double disk_mean_caustic(double x, double y, double r) { return disk_mean(x, y, r, -kA); }

// photon's radius of every round, from the schedule's definition.
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
// With `merged_direct` the direct light too is a disk mean (vcm's merges).
double expected_mean(int rounds, bool merged_direct = false) {
  const auto radii = round_radii(rounds);
  constexpr int n = kPixels * 4;
  double sum = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = kCentreX + kHalf * (2 * (i + 0.5) / n - 1), y = -kHalf * (2 * (j + 0.5) / n - 1);
      double caustic = 0, direct = rounds == 0 || !merged_direct ? irradiance(x, y, kA) : 0;
      if (rounds == 0) caustic = irradiance(x, y, -kA);
      for (double r : radii) {
        caustic += disk_mean_caustic(x, y, r) / rounds;
        if (merged_direct) direct += disk_mean(x, y, r, kA) / rounds;
      }
      sum += kRho / M_PI * (direct + caustic);
    }
  return sum / (n * n);
}

TEST(PhotonBias, FallsWithTheRoundsAsTheRadiusSchedulePredicts) {
  const auto scene = test::scene_from_xml(scene_xml("photon"));
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

// sppm's estimator simulated from its definition (Hachisuka and Jensen
// 2009), written here apart from integrators/photon. Every caustic photon
// brings the same flux, c = rho / pi times the light's power 4 pi I, so a
// pixel's estimate depends only on how many photons each iteration finds
// within its radius: of P photons, each lands in the disk with probability
// (the disk's caustic power) / (4 pi I), independently, and all iterations
// trace new photons. Each iteration the pixel's visible point is uniform
// over its footprint (box filter, orthographic camera), next-event
// estimation adds rho / pi times the direct irradiance there, and M photons
// found update N <- N + alpha M, R^2 <- R^2 (N + alpha M) / (N + M),
// tau <- (tau + M c) (N + alpha M) / (N + M). The image after n iterations
// is direct / n + tau / (n P pi R^2). The chains, many per pixel, give the
// expected image mean and mean squared radius with their standard errors.
struct SppmExpectation {
  double mean = 0, mean_se = 0, radius2 = 0, radius2_se = 0;
};

std::vector<SppmExpectation> simulate_sppm(const std::vector<int>& checkpoints, int photons, int chains) {
  std::mt19937_64 rng(2009);
  std::uniform_real_distribution<double> uniform(0, 1);
  const double flux = kRho / M_PI * 4 * M_PI * kIntensity, pixel = 2 * kHalf / kPixels;
  const size_t k = checkpoints.size();
  // Per checkpoint: sums over pixels of the chains' mean and of its variance.
  std::vector<double> mean(k), mean_var(k), radius2(k), radius2_var(k);
  for (int py = 0; py < kPixels; ++py)
    for (int px = 0; px < kPixels; ++px) {
      std::vector<double> sum(k), sum2(k), rsum(k), rsum2(k);
      for (int c = 0; c < chains; ++c) {
        double n_kept = 0, tau = 0, r2 = kRadius * kRadius, direct = 0;
        size_t next = 0;
        for (int i = 1; next < k; ++i) {
          const double x = kCentreX - kHalf + (px + uniform(rng)) * pixel;
          const double y = kHalf - (py + uniform(rng)) * pixel;
          direct += kRho / M_PI * irradiance(x, y, kA);
          const double r = std::sqrt(r2);
          const double p = M_PI * r2 * disk_mean_caustic(x, y, r) / (4 * M_PI * kIntensity);
          const double found = double(std::binomial_distribution<int>(photons, p)(rng));
          if (found > 0) {
            const double shrink = (n_kept + kAlpha * found) / (n_kept + found);
            tau = (tau + found * flux) * shrink;
            r2 *= shrink;
            n_kept += kAlpha * found;
          }
          if (i != checkpoints[next]) continue;
          const double estimate = direct / i + tau / (i * double(photons) * M_PI * r2);
          sum[next] += estimate;
          sum2[next] += estimate * estimate;
          rsum[next] += r2;
          rsum2[next] += r2 * r2;
          ++next;
        }
      }
      for (size_t j = 0; j < k; ++j) {
        mean[j] += sum[j] / chains;
        mean_var[j] += (sum2[j] / chains - (sum[j] / chains) * (sum[j] / chains)) / (chains - 1);
        radius2[j] += rsum[j] / chains;
        radius2_var[j] += (rsum2[j] / chains - (rsum[j] / chains) * (rsum[j] / chains)) / (chains - 1);
      }
    }
  constexpr double pixels = kPixels * kPixels;
  std::vector<SppmExpectation> out;
  for (size_t j = 0; j < k; ++j)
    out.push_back(
        {mean[j] / pixels, std::sqrt(mean_var[j]) / pixels, radius2[j] / pixels, std::sqrt(radius2_var[j]) / pixels});
  return out;
}

// One render's image mean and the squared rms radius it reports.
struct SppmRun {
  double mean, radius2;
};

SppmRun render_sppm(const LoadedScene& scene, int iterations, uint64_t seed) {
  RenderStats stats;
  const auto pixels = test::render_scene(scene, uint32_t(iterations), seed, 0, &stats).resolve();
  double sum = 0;
  for (float v : pixels) sum += v;
  const std::string prefix = "iterations=" + std::to_string(iterations) + ", rms radius=";
  EXPECT_THAT(stats.summary, testing::StartsWith(prefix));
  const double radius = std::stod(stats.summary.substr(prefix.size()));
  return {sum / double(pixels.size()), radius * radius};
}

TEST(SppmBias, ImageAndRadiusFollowTheEstimatorsDefinition) {
  const auto scene = test::scene_from_xml(scene_xml("sppm"));
  const std::vector<int> iterations = {1, 4, 16, 64};
  const auto model = simulate_sppm(iterations, 20000, 32);
  const double t_critical = test::two_sided_t_critical(test::sidak_alpha(0.01, 2 * int(iterations.size())), kRuns - 1);
  const double unbiased = expected_mean(0);
  uint64_t seed = 100;
  for (size_t j = 0; j < iterations.size(); ++j) {
    const int n = iterations[j];
    std::vector<double> means, radii2;
    for (int run = 0; run < kRuns; ++run) {
      const SppmRun r = render_sppm(scene, n, ++seed);
      means.push_back(r.mean);
      radii2.push_back(r.radius2);
    }
    const auto [mean, mean_se] = test::mean_and_standard_error(means);
    const auto [radius2, radius2_se] = test::mean_and_standard_error(radii2);
    EXPECT_LT(std::abs(mean - model[j].mean), t_critical * std::hypot(mean_se, model[j].mean_se))
        << n << " iterations: " << mean << " +- " << mean_se << ", model " << model[j].mean << " +- "
        << model[j].mean_se << " (bias " << model[j].mean - unbiased << ")";
    // After one iteration every pixel has found photons and R^2 = alpha R_0^2 exactly.
    if (n == 1) {
      EXPECT_NEAR(radius2, kAlpha * kRadius * kRadius, 1e-5 * kRadius * kRadius);
    } else {
      EXPECT_LT(std::abs(radius2 - model[j].radius2), t_critical * std::hypot(radius2_se, model[j].radius2_se))
          << n << " iterations: mean squared radius " << radius2 << " +- " << radius2_se << ", model "
          << model[j].radius2 << " +- " << model[j].radius2_se;
    }
    // The bias is large enough to tell one schedule from another, until
    // at 64 iterations it nears the noise.
    if (n <= 16) {
      EXPECT_GT(std::abs(mean - unbiased), 2 * t_critical * mean_se)
          << n << " iterations: the bias " << mean - unbiased << " is lost in the noise";
    }
  }
}

TEST(VcmMergeBias, FallsWithTheIterationsAsTheRadiusSchedulePredicts) {
  constexpr int kFilm = 32;
  const auto scene = test::scene_from_xml(scene_xml("vcm", kFilm));
  const std::vector<test::Region> whole{{{0, 0}, {kFilm, kFilm}}};
  const int iterations[] = {1, 4, 16, 64};
  const double t_critical = test::two_sided_t_critical(test::sidak_alpha(0.01, int(std::size(iterations))), kRuns - 1);
  const double unbiased = expected_mean(0);
  uint64_t seed = 500;
  for (int n : iterations) {
    uint64_t non_finite = 0;
    const test::RegionEstimate e =
        test::estimate_regions(scene, whole, uint32_t(n), kRuns, seed += kRuns, &non_finite)[0];
    EXPECT_EQ(non_finite, 0u);
    const double predicted = expected_mean(n, true);
    EXPECT_LT(std::abs(e.mean - predicted), t_critical * e.standard_error)
        << n << " iterations: " << e.mean << " +- " << e.standard_error << ", predicted " << predicted << " (bias "
        << predicted - unbiased << "), unbiased " << unbiased;
    // Fewer light paths than photon's photons: at 64 iterations the bias
    // nears the noise.
    if (n <= 16) {
      EXPECT_GT(std::abs(e.mean - unbiased), 2 * t_critical * e.standard_error)
          << n << " iterations: the bias " << e.mean - unbiased << " is too small to tell a schedule from another";
    }
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
