#pragma once

#include <memory>
#include <optional>
#include <unordered_map>
#include <vector>

#include "core/lights/emitter.h"
#include "core/sampling/discrete_distribution.h"

namespace caustica {

// Chooses an emitter in proportion to its power, so bright lights get the
// samples; an emitter of zero power is never chosen.
class LightSelection {
 public:
  explicit LightSelection(const std::vector<std::shared_ptr<Emitter>>& emitters);

  struct Choice {
    const Emitter* emitter;
    float pmf;
  };
  // u is remapped in place so the caller can reuse it.
  std::optional<Choice> sample(float& u) const;
  float pmf(const Emitter* emitter) const;
  bool empty() const { return !distribution_; }

 private:
  std::vector<const Emitter*> emitters_;
  std::unordered_map<const Emitter*, size_t> index_;
  std::optional<DiscreteDistribution> distribution_;
};

}  // namespace caustica
