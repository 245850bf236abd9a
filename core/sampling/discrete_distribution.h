#pragma once

#include <span>
#include <vector>

namespace caustica {

// Samples an index with probability proportional to its weight, by binary
// search over the cumulative distribution.
class DiscreteDistribution {
 public:
  // Throws std::invalid_argument if a weight is negative or not finite, or if
  // no weight is positive.
  explicit DiscreteDistribution(std::span<const float> weights);

  // Maps u in [0,1) to an index; entries of zero weight are never returned.
  // The optional outputs receive the index's probability and u rescaled to
  // [0,1) within the index's interval, so one number can drive two choices.
  int sample(float u, float* pmf = nullptr, float* u_remapped = nullptr) const;

  float pmf(int i) const { return pmf_[i]; }
  int size() const { return static_cast<int>(pmf_.size()); }
  float sum() const { return sum_; }

 private:
  std::vector<float> pmf_;
  // size() + 1 entries, from exactly 0 to exactly 1; a zero weight gives two
  // equal neighbours, an empty interval no u can fall into.
  std::vector<float> cdf_;
  float sum_ = 0;
};

}  // namespace caustica
