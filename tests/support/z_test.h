#pragma once

#include <cmath>

namespace caustica::test {

// The z such that a standard normal variable exceeds |z| with probability
// alpha (two-sided critical value), found by bisection on erfc.
inline double two_sided_z_critical(double alpha) {
  double lo = 0, hi = 40;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (std::erfc(mid / std::sqrt(2.0)) > alpha ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// The t such that Student's t with `dof` degrees of freedom exceeds |t|
// with probability alpha: for means whose variance is itself estimated from
// few independent runs. The density is integrated by Simpson's rule.
inline double two_sided_t_critical(double alpha, int dof) {
  const double nu = dof;
  const double norm = std::exp(std::lgamma((nu + 1) / 2) - std::lgamma(nu / 2)) / std::sqrt(nu * M_PI);
  const auto density = [&](double t) { return norm * std::pow(1 + t * t / nu, -(nu + 1) / 2); };
  const auto tail = [&](double t) {  // P(|T| > t)
    const int n = 4000;
    const double h = t / n;
    double sum = density(0) + density(t);
    for (int i = 1; i < n; ++i) sum += density(i * h) * (i % 2 ? 4 : 2);
    return 1 - 2 * sum * h / 3;
  };
  double lo = 0, hi = 1000;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (tail(mid) > alpha ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace caustica::test
