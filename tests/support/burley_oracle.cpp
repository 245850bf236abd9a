#include "tests/support/burley_oracle.h"

#include <algorithm>
#include <cmath>

namespace caustica::test::burley {

double dot3(Dir a, Dir b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

Dir unit(Dir a) {
  const double l = std::sqrt(dot3(a, a));
  return {a.x / l, a.y / l, a.z / l};
}

double schlick(double cos) { return std::pow(std::clamp(1 - cos, 0.0, 1.0), 5); }

double fresnel(double cos_i, double n1, double n2) {
  const double sin_t = n1 / n2 * std::sqrt(std::max(0.0, 1 - cos_i * cos_i));
  if (sin_t >= 1) return 1;
  const double cos_t = std::sqrt(1 - sin_t * sin_t);
  const double s = (n1 * cos_i - n2 * cos_t) / (n1 * cos_i + n2 * cos_t);
  const double p = (n2 * cos_i - n1 * cos_t) / (n2 * cos_i + n1 * cos_t);
  return (s * s + p * p) / 2;
}

Alphas alphas(double roughness, double anisotropic) {
  const double aspect = std::sqrt(1 - 0.9 * anisotropic), r2 = roughness * roughness;
  return {std::max(0.001, r2 / aspect), std::max(0.001, r2 * aspect)};
}

double ggx_D(Dir h, Alphas a) {
  const double theta = std::acos(h.z), phi = std::atan2(h.y, h.x);
  const double s2 = std::sin(theta) * std::sin(theta), c2 = std::cos(theta) * std::cos(theta);
  const double k =
      s2 * (std::cos(phi) * std::cos(phi) / (a.x * a.x) + std::sin(phi) * std::sin(phi) / (a.y * a.y)) + c2;
  return 1 / (M_PI * a.x * a.y * k * k);
}

double ggx_visibility(Dir v, Alphas a) {
  const double c = std::abs(v.z);
  return 1 / (c + std::sqrt(v.x * a.x * v.x * a.x + v.y * a.y * v.y * a.y + c * c));
}

double diffuse(double cos_l, double cos_v, double cos_d, double roughness, double flatness) {
  const double fl = schlick(cos_l), fv = schlick(cos_v);
  const double fd90 = 0.5 + 2 * roughness * cos_d * cos_d;
  const double fd = (1 + (fd90 - 1) * fl) * (1 + (fd90 - 1) * fv);
  const double fss90 = roughness * cos_d * cos_d;
  const double fss = (1 + (fss90 - 1) * fl) * (1 + (fss90 - 1) * fv);
  const double ss = 1.25 * (fss * (1 / (cos_l + cos_v) - 0.5) + 0.5);
  return (fd + flatness * (ss - fd)) / M_PI;
}

}  // namespace caustica::test::burley
