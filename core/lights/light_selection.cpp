#include "core/lights/light_selection.h"

#include <cmath>

#include "core/math/constants.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

float power_weight(const Emitter& e) {
  const float p = e.power().average();
  return std::isfinite(p) && p > 0 ? p : 0;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

LightSelection::LightSelection(const std::vector<std::shared_ptr<Emitter>>& emitters) {
  std::vector<float> weights, unbounded_weights;
  std::vector<LightBounds> bounds;
  for (const auto& e : emitters) {
    index_[e.get()] = emitters_.size();
    emitters_.push_back(e.get());
    const float w = power_weight(*e);
    weights.push_back(w);
    if (!(w > 0)) continue;
    if (const auto b = e->light_bounds()) {
      tree_index_[e.get()] = uint32_t(tree_emitters_.size());
      tree_emitters_.push_back(e.get());
      bounds.push_back(*b);
    } else {
      unbounded_index_[e.get()] = unbounded_.size();
      unbounded_.push_back(e.get());
      unbounded_weights.push_back(w);
    }
  }
  bool any = false;
  for (float w : weights) any = any || w > 0;
  if (any) distribution_.emplace(weights);
  if (!tree_emitters_.empty()) tree_.emplace(bounds);
  if (!unbounded_.empty()) unbounded_distribution_.emplace(unbounded_weights);
  const auto k = float(unbounded_.size());
  unbounded_share_ = unbounded_.empty() ? 0 : !tree_ ? 1 : k / (k + 1);
}

std::optional<LightSelection::Choice> LightSelection::sample(float& u) const {
  if (!distribution_) return std::nullopt;
  float pmf = 0, remapped = 0;
  const size_t i = distribution_->sample(u, &pmf, &remapped);
  u = remapped;
  return Choice{emitters_[i], pmf};
}

float LightSelection::pmf(const Emitter* emitter) const {
  if (!distribution_) return 0;
  const auto it = index_.find(emitter);
  return it == index_.end() ? 0 : distribution_->pmf(it->second);
}

std::optional<LightSelection::Choice> LightSelection::sample(float& u, const ReferencePoint& ref) const {
  const float share = unbounded_share_;
  if (u < share) {
    u = std::min(u / share, kOneMinusEpsilon);
    float pmf = 0, remapped = 0;
    const size_t i = unbounded_distribution_->sample(u, &pmf, &remapped);
    u = remapped;
    return Choice{unbounded_[i], share * pmf};
  }
  if (!tree_) return std::nullopt;
  u = std::min((u - share) / (1 - share), kOneMinusEpsilon);
  const auto choice = tree_->sample(u, ref.p, ref.n);
  if (!choice) return std::nullopt;
  return Choice{tree_emitters_[choice->light], (1 - share) * choice->pmf};
}

float LightSelection::pmf(const Emitter* emitter, const ReferencePoint& ref) const {
  const float share = unbounded_share_;
  if (const auto it = tree_index_.find(emitter); it != tree_index_.end())
    return (1 - share) * tree_->pmf(it->second, ref.p, ref.n);
  if (const auto it = unbounded_index_.find(emitter); it != unbounded_index_.end())
    return share * unbounded_distribution_->pmf(it->second);
  return 0;
}

}  // namespace caustica
