#include "core/lights/light_tree.h"

#include <algorithm>
#include <cmath>

#include "core/math/constants.h"

namespace caustica {

LightTree::LightTree(const std::vector<LightBounds>& lights) : trail_(lights.size(), 0), depth_(lights.size(), -1) {
  std::vector<uint32_t> order;
  for (uint32_t i = 0; i < lights.size(); ++i)
    if (lights[i].phi > 0 && std::isfinite(lights[i].phi)) order.push_back(i);
  if (order.empty()) return;
  nodes_.reserve(2 * order.size() - 1);
  build(order.begin(), order.end(), lights);
  // Each light's trail, read back from the tree.
  struct Step {
    uint32_t node;
    uint64_t trail;
    int depth;
  };
  std::vector<Step> stack{{0, 0, 0}};
  while (!stack.empty()) {
    const Step s = stack.back();
    stack.pop_back();
    const Node& node = nodes_[s.node];
    if (node.second == 0) {
      trail_[node.light] = s.trail;
      depth_[node.light] = s.depth;
      continue;
    }
    stack.push_back({s.node + 1, s.trail, s.depth + 1});
    stack.push_back({node.second, s.trail | (uint64_t(1) << s.depth), s.depth + 1});
  }
}

// Halves the lights at the median of their centres along the axis where
// the centres spread widest, so the tree is balanced (depth log2 of the
// number of lights, far below the trails' 64 bits).
uint32_t LightTree::build(std::vector<uint32_t>::iterator begin, std::vector<uint32_t>::iterator end,
                          const std::vector<LightBounds>& lights) {
  const auto index = uint32_t(nodes_.size());
  nodes_.emplace_back();
  if (end - begin == 1) {
    nodes_[index].light = *begin;
    set_bounds(nodes_[index], lights[*begin]);
    return index;
  }
  Bounds3 centres;
  for (auto it = begin; it != end; ++it) centres.expand(lights[*it].bounds.center());
  const Vec3 extent = centres.hi - centres.lo;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  const auto middle = begin + (end - begin) / 2;
  std::nth_element(begin, middle, end, [&](uint32_t a, uint32_t b) {
    const float ca = lights[a].bounds.center()[axis], cb = lights[b].bounds.center()[axis];
    return ca < cb || (ca == cb && a < b);
  });
  build(begin, middle, lights);
  const uint32_t second = build(middle, end, lights);
  nodes_[index].second = second;
  set_bounds(nodes_[index], LightBounds::merge(nodes_[index + 1].bounds, nodes_[second].bounds));
  return index;
}

void LightTree::set_bounds(Node& node, const LightBounds& bounds) {
  node.bounds = bounds;
  node.centre = bounds.bounds.center();
  node.radius = bounding_radius(bounds.bounds);
}

float LightTree::first_child_probability(const Node& node, Vec3 p, Vec3 n) const {
  const Node& a = nodes_[&node - nodes_.data() + 1];
  const Node& b = nodes_[node.second];
  const double first = light_importance(a.bounds, a.centre, a.radius, p, n);
  const double second = light_importance(b.bounds, b.centre, b.radius, p, n);
  if (!(first + second > 0)) return -1;
  return float(first / (first + second));
}

std::optional<LightTree::Choice> LightTree::sample(float& u, Vec3 p, Vec3 n) const {
  if (nodes_.empty()) return std::nullopt;
  uint32_t at = 0;
  float pmf = 1;
  while (nodes_[at].second != 0) {
    const float first = first_child_probability(nodes_[at], p, n);
    if (first < 0) return std::nullopt;
    if (u < first) {
      u = std::min(u / first, kOneMinusEpsilon);
      pmf *= first;
      at = at + 1;
    } else {
      u = std::min((u - first) / (1 - first), kOneMinusEpsilon);
      pmf *= 1 - first;
      at = nodes_[at].second;
    }
  }
  return Choice{nodes_[at].light, pmf};
}

float LightTree::pmf(uint32_t light, Vec3 p, Vec3 n) const {
  if (light >= depth_.size() || depth_[light] < 0) return 0;
  uint32_t at = 0;
  float pmf = 1;
  for (int depth = 0; depth < depth_[light]; ++depth) {
    const float first = first_child_probability(nodes_[at], p, n);
    if (first < 0) return 0;
    if (trail_[light] >> depth & 1) {
      pmf *= 1 - first;
      at = nodes_[at].second;
    } else {
      pmf *= first;
      at = at + 1;
    }
  }
  return pmf;
}

}  // namespace caustica
