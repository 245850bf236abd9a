#include "core/sampling/discrete_distribution.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/math/branchless_upper_bound.h"
#include "core/math/constants.h"

namespace caustica {

DiscreteDistribution::DiscreteDistribution(std::span<const float> weights) {
  // Double accumulation keeps the CDF accurate for long weight arrays such as
  // environment map rows.
  double total = 0;
  for (size_t i = 0; i < weights.size(); ++i) {
    const float w = weights[i];
    if (!std::isfinite(w) || w < 0)
      throw std::invalid_argument("DiscreteDistribution: weight " + std::to_string(i) + " is " + std::to_string(w) +
                                  ", but weights must be finite and non-negative");
    total += w;
  }
  if (!(total > 0)) throw std::invalid_argument("DiscreteDistribution: needs at least one positive weight");

  pmf_.resize(weights.size());
  cdf_.resize(weights.size() + 1);
  double prefix = 0;
  cdf_[0] = 0;
  for (size_t i = 0; i < weights.size(); ++i) {
    pmf_[i] = static_cast<float>(weights[i] / total);
    prefix += weights[i];
    cdf_[i + 1] = static_cast<float>(prefix / total);
  }
  cdf_.back() = 1;
  sum_ = static_cast<float>(total);
}

int DiscreteDistribution::sample(float u, float* pmf, float* u_remapped) const {
  // Clamping keeps u below cdf_.back() == 1, which guarantees that the search
  // lands on a non-empty interval even for an out-of-range u.
  u = std::clamp(u, 0.0f, kOneMinusEpsilon);
  // The first CDF entry above u closes the interval that holds u; runs of
  // equal entries (zero weights) are skipped by the strict comparison.
  const int i = static_cast<int>(branchless_upper_bound(cdf_, u)) - 1;
  if (pmf) *pmf = pmf_[i];
  if (u_remapped) {
    const float lo = cdf_[i], hi = cdf_[i + 1];
    *u_remapped = std::min((u - lo) / (hi - lo), kOneMinusEpsilon);
  }
  return i;
}

}  // namespace caustica
