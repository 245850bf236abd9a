#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/loader/scene_loader.h"
#include "core/math/vec.h"

namespace caustica::test {

// The mean of values from independent runs and its standard error.
std::pair<double, double> mean_and_standard_error(const std::vector<double>& values);

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
// `non_finite`, if given, receives the number of samples and splats the
// film dropped for not being finite, plus the non-finite pixels.
std::vector<RegionEstimate> estimate_regions(const LoadedScene& scene, const std::vector<Region>& regions, uint32_t spp,
                                             int runs, uint64_t first_seed, uint64_t* non_finite = nullptr);

// Whether any camera ray within the filter's reach of the region first
// meets a surface with a delta lobe: light paths cannot reach a pinhole
// through such a surface, so light tracing leaves these regions dark.
bool seen_through_delta(const Scene& scene, const Region& region);

// The region means of the stored path reference of scenes/NAME.xml
// (tests/data/references, 24x24) and their standard errors from its
// per-pixel variance layers (taking its channels as fully correlated, an
// upper bound).
std::vector<RegionEstimate> reference_regions(const std::string& name, const std::vector<Region>& regions);

// (a - b) / sqrt(se_a^2 + se_b^2), for a two-sample test; a small relative
// rounding spread keeps noise-free estimates comparable.
double difference_score(const RegionEstimate& a, const RegionEstimate& b);

// Whether a region's estimate agrees with a value known exactly (a closed
// form): |difference_score| below t_critical; the failure names the region
// and both values.
testing::AssertionResult agrees_with_exact(const Region& region, const RegionEstimate& estimate, double exact,
                                           double t_critical);

}  // namespace caustica::test
