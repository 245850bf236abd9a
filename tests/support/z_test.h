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

}  // namespace caustica::test
