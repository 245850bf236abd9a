#pragma once

#include <memory>
#include <optional>
#include <unordered_map>
#include <vector>

#include "core/geometry/reference_point.h"
#include "core/lights/emitter.h"
#include "core/lights/light_tree.h"
#include "core/sampling/discrete_distribution.h"

namespace caustica {

// Chooses an emitter: in proportion to its power (for paths that start on
// a light), or, for a point to be lit, through the light tree over the
// emitters it can bound, so that near and bright lights get that point's
// samples. An emitter of zero power is never chosen.
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

  // The choice for lighting `ref`. The emitters the tree cannot bound (the
  // environment, directional and moving lights) are chosen by power among
  // themselves, with probability k / (k + 1) for k of them (1 where the
  // tree is empty); the tree takes the rest.
  std::optional<Choice> sample(float& u, const ReferencePoint& ref) const;
  float pmf(const Emitter* emitter, const ReferencePoint& ref) const;
  // How many emitters the tree holds.
  size_t tree_lights() const { return tree_emitters_.size(); }

 private:
  std::vector<const Emitter*> emitters_;
  std::unordered_map<const Emitter*, size_t> index_;
  std::optional<DiscreteDistribution> distribution_;

  std::vector<const Emitter*> tree_emitters_;
  std::unordered_map<const Emitter*, uint32_t> tree_index_;
  std::optional<LightTree> tree_;
  std::vector<const Emitter*> unbounded_;
  std::unordered_map<const Emitter*, size_t> unbounded_index_;
  std::optional<DiscreteDistribution> unbounded_distribution_;
  float unbounded_share_ = 0;  // k / (k + 1), or 1 where the tree is empty
};

}  // namespace caustica
