#include "core/lights/light_selection.h"

namespace caustica {

LightSelection::LightSelection(const std::vector<std::shared_ptr<Emitter>>& emitters) {
  std::vector<float> weights;
  for (const auto& e : emitters) {
    index_[e.get()] = emitters_.size();
    emitters_.push_back(e.get());
    const float p = e->power().average();
    weights.push_back(std::isfinite(p) && p > 0 ? p : 0);
  }
  bool any = false;
  for (float w : weights) any = any || w > 0;
  if (any) distribution_.emplace(weights);
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

}  // namespace caustica
