#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/math/constants.h"
#include "core/math/vec.h"
#include "integrators/path/guiding/fixed_point_sum.h"

namespace caustica {

// Directions as points of the unit square by the cylindrical map
// (cos theta, phi / 2 pi), which keeps areas: a density over the square is
// 4 pi times the density over the sphere of the same directions.
Vec2 direction_to_square(Vec3 w);
Vec3 square_to_direction(Vec2 p);
inline constexpr float kSquareToSphere = 1 / (4 * kPi);

// The shape of a quadtree over the unit square: node 0 is the root; each
// node has four quadrants, (x, y) halves numbered x + 2 y, each either a
// leaf or another node (0 marks a leaf, as the root is no child).
struct QuadtreeShape {
  std::vector<std::array<uint32_t, 4>> children{{0, 0, 0, 0}};
  size_t nodes() const { return children.size(); }
};

// A piecewise-constant density over the unit square: the quadrants of a
// quadtree, each with the share of the energy recorded in it. Sampling
// descends from the root choosing quadrants by their energy, then places
// the point uniformly in the leaf quadrant reached; the density there is
// the leaf's share of the energy over its share of the area.
class DirectionalDistribution {
 public:
  // Uniform: no energy recorded.
  DirectionalDistribution() : energy_(1) {}
  DirectionalDistribution(QuadtreeShape shape, std::vector<std::array<double, 4>> energy);

  struct Sample {
    Vec2 p;
    float pdf;  // over the unit square
  };
  // From a uniform point of the square. Never returns a point of zero density.
  Sample sample(Vec2 u) const;
  float pdf(Vec2 p) const;
  double total() const;
  bool empty() const { return !(total() > 0); }
  const QuadtreeShape& shape() const { return shape_; }
  const std::array<double, 4>& energy(uint32_t node) const { return energy_[node]; }
  size_t bytes() const;

 private:
  QuadtreeShape shape_;
  std::vector<std::array<double, 4>> energy_;  // per node and quadrant, the sum over what lies inside
};

// Records energy into the leaf quadrants of a quadtree of fixed shape,
// from many threads at once, so that the sums are the same whatever the
// order (FixedPointSum); read them once every record has returned.
class DirectionalRecorder {
 public:
  explicit DirectionalRecorder(QuadtreeShape shape = {});
  void record(Vec2 p, double energy);
  // The same energy spread evenly over a square the size of the leaf
  // quadrant holding p, centred on p (the part outside the unit square is
  // dropped), each quadrant it overlaps taking its share: a record then
  // teaches its neighbourhood, not one quadrant alone.
  void record_spread(Vec2 p, double energy);
  // The energies recorded, summed up the tree.
  DirectionalDistribution distribution() const;
  const QuadtreeShape& shape() const { return shape_; }
  size_t bytes() const { return bytes_for(shape_); }
  static size_t bytes_for(const QuadtreeShape& shape);

 private:
  void splat(uint32_t node, double x0, double y0, double size, const double box[4], double density);

  QuadtreeShape shape_;
  std::unique_ptr<std::array<FixedPointSum, 4>[]> sums_;  // per node, as many as the shape has
};

// The shape for the next pass's records: a quadrant holding more than
// `threshold` of the total energy is divided, down to `max_depth` levels;
// quadrants the distribution does not divide are taken to hold their
// energy evenly. With no energy, the root alone.
QuadtreeShape refined_shape(const DirectionalDistribution& d, double threshold, int max_depth);

}  // namespace caustica
