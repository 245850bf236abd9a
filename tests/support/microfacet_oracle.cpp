#include "tests/support/microfacet_oracle.h"

#include <cmath>
#include <vector>

namespace caustica::test {

namespace {

struct D3 {
  double x, y, z;
};
D3 operator*(double s, D3 v) { return {s * v.x, s * v.y, s * v.z}; }
D3 operator-(D3 a, D3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
double dot(D3 a, D3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

double lambda(const MicrofacetModel& model, D3 w) {
  const double xy2 = w.x * w.x + w.y * w.y;
  if (xy2 == 0) return 0;
  const double alpha2 = (w.x * w.x * model.alpha_u * model.alpha_u + w.y * w.y * model.alpha_v * model.alpha_v) / xy2;
  const double tan2 = xy2 / (w.z * w.z);
  if (model.ggx) return (-1 + std::sqrt(1 + alpha2 * tan2)) / 2;
  const double a = 1 / std::sqrt(alpha2 * tan2);
  return (std::erf(a) - 1) / 2 + std::exp(-a * a) / (2 * a * std::sqrt(M_PI));
}

}  // namespace

// rs = (c - eta ct) / (c + eta ct), rp = (eta c - ct) / (eta c + ct).
double fresnel_reflectance(double c, double eta) {
  const double sin2_t = (1 - c * c) / (eta * eta);
  if (sin2_t >= 1) return 1;
  const double ct = std::sqrt(1 - sin2_t);
  const double rs = (c - eta * ct) / (c + eta * ct), rp = (eta * c - ct) / (eta * c + ct);
  return (rs * rs + rp * rp) / 2;
}

double smith_lambda(const MicrofacetModel& model, Vec3 w) { return lambda(model, {w.x, w.y, w.z}); }

MicrofacetAlbedo microfacet_albedo(const MicrofacetModel& model, const Interface& interface, Vec3 wo_f, int n) {
  const D3 wo{wo_f.x, wo_f.y, wo_f.z};
  const double lambda_o = lambda(model, wo);
  const int n_phi = 2 * n;
  std::vector<double> cos_phi(n_phi), sin_phi(n_phi);
  for (int j = 0; j < n_phi; ++j) {
    cos_phi[j] = std::cos(2 * M_PI * (j + 0.5) / n_phi);
    sin_phi[j] = std::sin(2 * M_PI * (j + 0.5) / n_phi);
  }
  MicrofacetAlbedo sum;
  for (int i = 0; i < n; ++i) {
    // u = 1 - s^2 takes the 1 / cos(theta_m) of steep facets out of the
    // integrand: du / sqrt(1 - u) = 2 ds.
    const double s = (i + 0.5) / n, u = 1 - s * s, du = 2 * s / n;
    const double r = model.ggx ? std::sqrt(u) / s : std::sqrt(-2 * std::log(s));
    for (int j = 0; j < n_phi; ++j) {
      // D(m) cos(theta_m) dm is the slope distribution stretched by the
      // roughness, so du dphi / (2 pi) is its measure.
      const double sx = model.alpha_u * r * cos_phi[j], sy = model.alpha_v * r * sin_phi[j];
      const double norm = std::sqrt(1 + sx * sx + sy * sy);
      const D3 m{-sx / norm, -sy / norm, 1 / norm};
      const double c = dot(wo, m);
      if (c <= 0) continue;
      const double weight = du / n_phi * c / (wo.z * m.z);
      const double F = interface.dielectric ? fresnel_reflectance(c, interface.eta) : 1;
      const D3 wr = 2 * c * m - wo;
      if (wr.z > 0) sum.reflected += weight * F / (1 + lambda_o + lambda(model, wr));
      if (interface.dielectric && F < 1) {
        const double eta = interface.eta, cos_t = std::sqrt(1 - (1 - c * c) / (eta * eta));
        const D3 wt = (c / eta - cos_t) * m - (1 / eta) * wo;
        if (wt.z < 0) sum.refracted += weight * (1 - F) / (1 + lambda_o + lambda(model, wt));
      }
    }
  }
  return sum;
}

}  // namespace caustica::test
