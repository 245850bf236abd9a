#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/lights/light_bounds.h"

namespace caustica {

// A binary tree over emitters that chooses one for a shading point in
// proportion, level by level, to how much each subtree may light that
// point (light_importance): the light-tree selection of Conty Estevez and
// Kulla (2018), as pbrt-v4 and Cycles use it. Choosing among hundreds of
// lights by power alone sends most shadow rays to lights far from the
// point; the tree sends them to the near and bright ones. A light that can
// light the point always keeps a positive probability, so every estimate
// stays unbiased; sample() and pmf() walk the same tree and agree exactly.
class LightTree {
 public:
  // Lights of zero power are left out (never chosen).
  explicit LightTree(const std::vector<LightBounds>& lights);

  struct Choice {
    uint32_t light;  // index into the constructor's vector
    float pmf;
  };
  // u is remapped in place so the caller can reuse it.
  std::optional<Choice> sample(float& u, Vec3 p, Vec3 n) const;
  float pmf(uint32_t light, Vec3 p, Vec3 n) const;
  bool empty() const { return nodes_.empty(); }

 private:
  struct Node {
    LightBounds bounds;
    Vec3 centre;  // of the bounds' bounding sphere
    float radius = 0;
    uint32_t second = 0;  // an inner node's second child (its first follows it); 0 for a leaf
    uint32_t light = 0;   // a leaf's light
  };
  // The probability of taking the node's first child, or -1 where neither
  // child can light the point.
  float first_child_probability(const Node& node, Vec3 p, Vec3 n) const;
  static void set_bounds(Node& node, const LightBounds& bounds);
  uint32_t build(std::vector<uint32_t>::iterator begin, std::vector<uint32_t>::iterator end,
                 const std::vector<LightBounds>& lights);

  std::vector<Node> nodes_;
  // Per light, the turns from the root to its leaf (bit i set: the second
  // child at depth i) and its depth; depth -1 for a light left out.
  std::vector<uint64_t> trail_;
  std::vector<int> depth_;
};

}  // namespace caustica
