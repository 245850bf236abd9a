#pragma once

#include <vector>

#include "core/math/vec.h"
#include "core/registry/plugin.h"

namespace caustica {

struct FilterSample {
  Vec2 offset;  // from the pixel centre, in pixels
  float weight = 1;
};

// A separable pixel reconstruction filter f(x) f(y). Rather than splatting a
// sample onto every pixel in reach, each pixel draws its sample positions
// from the filter itself and weights them by f / pdf (filter importance
// sampling): a pixel is then written only by its own samples, which keeps
// images bit-identical for any thread count and tile order.
class ReconstructionFilter : public Plugin {
 public:
  float radius() const { return radius_; }
  virtual float eval(float x) const = 0;
  // The integral of |f| over [-radius, radius], which normalises splats.
  float integral() const { return cdf_.back(); }
  FilterSample sample(Vec2 u) const;

 protected:
  // Tabulates eval over [-radius, radius] for sampling; call once eval works.
  void init(float radius);

 private:
  float sample_1d(float u, float* weight) const;

  float radius_ = 0.5f;
  std::vector<float> cdf_;  // piecewise-linear CDF of |f| over equal cells
  std::vector<float> cell_;
  // For each of kCells equal slices of [0, integral), the last cell whose CDF
  // lies at or below the slice's start: sampling scans a cell or two from
  // there instead of a binary search, and finds the same cell.
  std::vector<int> guide_;
};

}  // namespace caustica
