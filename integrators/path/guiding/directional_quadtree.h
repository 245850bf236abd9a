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
  DirectionalDistribution() : energy_(1), steps_(1) {}
  DirectionalDistribution(QuadtreeShape shape, std::vector<std::array<double, 4>> energy);

  struct Sample {
    Vec2 p;
    float pdf;  // over the unit square
    Vec2 leaf;  // the lower corner of the leaf quadrant p lies in
    float leaf_size;
  };
  // From a uniform point of the square. Never returns a point of zero density.
  Sample sample(Vec2 u) const;
  float pdf(Vec2 p) const;
  // pdf(p), read from s where p lies in s's leaf (the density there is s's,
  // to the bit): a direction sampled and mapped back to the square mostly
  // lands where it was drawn, and the descent is then spared.
  float pdf_near(const Sample& s, Vec2 p) const {
    const bool inside =
        p.x >= s.leaf.x && p.x - s.leaf.x < s.leaf_size && p.y >= s.leaf.y && p.y - s.leaf.y < s.leaf_size;
    return inside ? s.pdf : pdf(p);
  }
  double total() const { return total_; }
  bool empty() const { return !(total_ > 0); }
  const QuadtreeShape& shape() const { return shape_; }
  const std::array<double, 4>& energy(uint32_t node) const { return energy_[node]; }
  size_t bytes() const;

 private:
  // What a descent reads at a node, in one place: every path vertex reads
  // a guide's density at least twice, and the sums above, spread over two
  // arrays of doubles, cost it a division per level and twice the cache
  // lines. Densities and probabilities are rounded to float from the
  // doubles, so a zero stays zero and a quadrant of any energy keeps some.
  struct Step {
    std::array<uint32_t, 4> children;
    std::array<float, 4> density;  // each quadrant's, relative to the node's: 4 e_q / sum
    float lower_x;                 // the probability of the quadrants of x < 1/2
    std::array<float, 2> lower_y;  // of y < 1/2, given the half of x chosen
  };

  QuadtreeShape shape_;
  std::vector<std::array<double, 4>> energy_;  // per node and quadrant, the sum over what lies inside
  std::vector<Step> steps_;                    // per node, from energy_
  double total_ = 0;
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
