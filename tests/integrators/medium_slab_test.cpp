// A slab of isotropically scattering medium (optical thickness T, albedo
// w) lit from behind by a diffuse emitter of radiance 1, seen head-on from
// the other side by an orthographic camera: its transmitted radiance at
// normal exitance against a numerical solution of the one-dimensional
// transfer equation written here, apart from the renderer:
//   mu dI/dtau = -I + S,   S(tau) = (w / 2) int_{-1}^{1} I(tau, mu') dmu',
// with I = 1 entering at tau = 0 (mu > 0) and nothing at tau = T (mu < 0),
// solved by iterating S on a fine grid of layers (the formal solution is
// exact for S constant in a layer) with Gauss-Legendre directions. The
// single-scattering answer (max_depth 2: the camera ray, one event, the
// light) is the first iterate. path and bdpt render it (the orthographic
// camera leaves bdpt its strategies that start from the camera). Each
// check is a z-test of the image mean at 0.1%, Sidak-corrected over the
// file's checks; seeds are fixed.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tests/support/test_scenes.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

constexpr int kChecks = 2 * 3;
const double kZCritical = test::two_sided_z_critical(1 - std::pow(1 - 0.001, 1.0 / kChecks));

// Gauss-Legendre nodes and weights on [0, 1], by Newton's method on P_n.
void gauss_legendre(int n, std::vector<double>& x, std::vector<double>& w) {
  x.resize(n);
  w.resize(n);
  for (int i = 0; i < n; ++i) {
    double z = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 0;
    for (int iter = 0; iter < 100; ++iter) {
      double p0 = 1, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1);
      const double step = p1 / dp;
      z -= step;
      if (std::abs(step) < 1e-15) break;
    }
    x[i] = (1 - z) / 2;
    w[i] = 1 / ((1 - z * z) * dp * dp);  // the [-1, 1] weight 2 / (...), halved for [0, 1]
  }
}

// The radiance leaving tau = T along mu = 1, with `orders` scattering
// orders (0 for all of them, iterated to convergence).
double slab_transmission(double T, double albedo, int orders) {
  const int layers = 4000, directions = 48;
  const double h = T / layers;
  std::vector<double> mu, weight;
  gauss_legendre(directions, mu, weight);
  std::vector<double> S(layers, 0.0), next(layers);
  const int iterations = orders > 0 ? orders : 10000;
  for (int it = 0; it < iterations; ++it) {
    std::fill(next.begin(), next.end(), 0.0);
    for (int j = 0; j < directions; ++j) {
      const double a = std::exp(-h / mu[j]);
      // Upward (mu > 0) from the emitter: the mean over each layer of I.
      double I = 1;
      for (int k = 0; k < layers; ++k) {
        // Exact mean of I over the layer for constant S: S + (I0 - S) (1 - a) mu / h.
        next[k] += weight[j] * (S[k] + (I - S[k]) * (1 - a) * mu[j] / h);
        I = I * a + S[k] * (1 - a);
      }
      // Downward from the dark side.
      I = 0;
      for (int k = layers - 1; k >= 0; --k) {
        next[k] += weight[j] * (S[k] + (I - S[k]) * (1 - a) * mu[j] / h);
        I = I * a + S[k] * (1 - a);
      }
    }
    double change = 0;
    for (int k = 0; k < layers; ++k) {
      // (w / 2) times the integral over mu in [-1, 1]: each hemisphere's weights sum to 1.
      const double s = albedo / 2 * next[k];
      change = std::max(change, std::abs(s - S[k]));
      S[k] = s;
    }
    if (orders == 0 && change < 1e-12) break;
  }
  // Along mu = 1 through the whole slab.
  const double a = std::exp(-h);
  double I = 1;
  for (int k = 0; k < layers; ++k) I = I * a + S[k] * (1 - a);
  return I;
}

std::string slab_scene(const std::string& integrator, double T, double albedo, int max_depth) {
  // The slab spans z in [0.01, 1.01] and 400 units across; the emitter
  // below it is black to what falls on it.
  return "<scene version='3.0.0'><integrator type='" + integrator + "'><integer name='max_depth' value='" +
         std::to_string(max_depth) +
         "'/></integrator>"
         "<medium type='homogeneous' id='slab'><float name='sigma_t' value='" +
         std::to_string(T) + "'/><float name='albedo' value='" + std::to_string(albedo) +
         "'/></medium>"
         "<sensor type='orthographic'><transform name='to_world'><scale x='0.1' y='0.1'/>"
         "<lookat origin='0, 0, 5' target='0, 0, 0' up='0, 1, 0'/></transform><sampler type='independent'/>"
         "<film type='hdrfilm'><integer name='width' value='16'/><integer name='height' value='16'/>"
         "<rfilter type='box'/></film></sensor>"
         "<shape type='cube'><transform name='to_world'><scale x='200' y='200' z='0.5'/><translate z='0.51'/>"
         "</transform><ref name='interior' id='slab'/></shape>"
         "<shape type='rectangle'><transform name='to_world'><scale value='200'/></transform>"
         "<bsdf type='diffuse'><rgb name='reflectance' value='0'/></bsdf>"
         "<emitter type='area'><rgb name='radiance' value='1'/></emitter></shape></scene>";
}

class MediumSlab : public testing::TestWithParam<const char*> {
 protected:
  void expect_slab(double T, double albedo, int max_depth, int orders, uint64_t seed) const;
};

void MediumSlab::expect_slab(double T, double albedo, int max_depth, int orders, uint64_t seed) const {
  const double expected = slab_transmission(T, albedo, orders);
  const auto scene = test::scene_from_xml(slab_scene(GetParam(), T, albedo, max_depth));
  const FilmBuffer film = test::render_scene(scene, 256, seed);
  const auto img = film.resolve();
  const auto var = film.variance();
  double sum = 0, var_sum = 0;
  for (size_t i = 0; i < img.size(); i += 3) {
    sum += img[i];
    var_sum += var[i];
  }
  const double pixels = double(img.size() / 3), mean = sum / pixels, standard_error = std::sqrt(var_sum) / pixels;
  EXPECT_LT(std::abs(mean - expected), kZCritical * standard_error)
      << GetParam() << ", T " << T << ", albedo " << albedo << ", max_depth " << max_depth << ": " << mean << " +- "
      << standard_error << ", expected " << expected;
}

TEST_P(MediumSlab, TransmissionMatchesTheOneDimensionalSolution) {
  expect_slab(1, 0.8, -1, 0, 1);
  expect_slab(2, 0.95, -1, 0, 2);
}

TEST_P(MediumSlab, SingleScatteringMatchesTheFirstOrder) { expect_slab(1, 0.8, 2, 1, 3); }

INSTANTIATE_TEST_SUITE_P(Integrators, MediumSlab, testing::Values("path", "bdpt"), test::scene_test_name);

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
