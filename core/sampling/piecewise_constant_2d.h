#pragma once

#include <optional>
#include <span>
#include <vector>

#include "core/math/vec.h"
#include "core/sampling/discrete_distribution.h"

namespace caustica {

// A density over [0,1)^2 constant on each cell of a width x height grid,
// proportional to the cell's weight: a row is chosen by its total, then a
// cell within it, then a point uniformly within the cell.
class PiecewiseConstant2D {
 public:
  // Weights row by row, top row first. Throws std::invalid_argument if a
  // weight is negative or not finite, or if none is positive.
  PiecewiseConstant2D(std::span<const float> weights, int width, int height);

  // A point of [0,1)^2 and its density there.
  Vec2 sample(Vec2 u, float* pdf) const;
  float pdf(Vec2 p) const;

 private:
  int width_, height_;
  DiscreteDistribution rows_;
  std::vector<std::optional<DiscreteDistribution>> columns_;  // empty for rows of zero weight
};

}  // namespace caustica
