#pragma once

#include <cstdint>
#include <vector>

#include "core/math/vec.h"
#include "core/scene/scene.h"

namespace caustica::test {

// A rectangle of pixels [lo, hi).
struct Region {
  Vec2i lo, hi;
};

// The width / n by height / n blocks that tile the film.
std::vector<Region> grid_regions(int width, int height, int n);

// The mean over a region's pixels and channels (R, G, B), as estimated by
// `runs` renders with independent seeds: the mean of their region means and
// its standard error from their spread. Splatting integrators have no
// per-pixel variance, so this is how their error is known.
struct RegionEstimate {
  double mean = 0, standard_error = 0;
  int runs = 0;
};
std::vector<RegionEstimate> estimate_regions(const Scene& scene, const std::vector<Region>& regions, uint32_t spp,
                                             int runs, uint64_t first_seed);

// (a - b) / sqrt(se_a^2 + se_b^2), for a two-sample test; a small relative
// rounding spread keeps noise-free estimates comparable.
double difference_score(const RegionEstimate& a, const RegionEstimate& b);

}  // namespace caustica::test
