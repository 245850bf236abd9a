#include "core/bsdf/fresnel.h"

namespace caustica {

float internal_diffuse_reflectance(float eta) {
  const double mu_c = eta > 1 ? std::sqrt(1 - 1 / (double(eta) * eta)) : 0.0;
  const int n = 1024;  // even
  double sum = 0;
  for (int i = 0; i <= n; ++i) {
    const double s = double(i) / n, mu = mu_c + (1 - mu_c) * s * s;
    const double value = fresnel_dielectric(float(-mu), eta).F * mu * 2 * (1 - mu_c) * s;
    sum += value * (i == 0 || i == n ? 1 : (i % 2 ? 4 : 2));
  }
  return float(mu_c * mu_c + 2 * sum / (3 * n));
}

}  // namespace caustica
