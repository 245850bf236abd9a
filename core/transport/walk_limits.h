#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>

#include "core/render/path_settings.h"
#include "core/transport/russian_roulette.h"

namespace caustica {

// The most segments a walk takes when max_depth gives no limit (-1).
// Roulette ends paths whose throughput falls, but not one that keeps its
// throughput: in a dense medium of albedo 1 a path scatters about
// (optical depth)^2 times before it leaves, for ever at a sigma_t of 1e10.
// Where a path reaches this bound it is cut, losing what its longer part
// would have carried.
inline constexpr int64_t kLongestWalk = 4096;

// How far a walk may go.
struct WalkLimits {
  // Segments from the walk's origin to its last vertex; -1 for no limit.
  // At a vertex this many segments out nothing is sampled any more.
  int64_t max_segments = -1;
  RussianRoulette roulette;
};

// The walks path settings allow. A camera walk may have max_depth
// segments; a light walk one fewer, since its last vertex still needs the
// segment to the camera. Light walks roulette at any throughput: photons
// left to bounce until they fall below rr_threshold made an sppm pass 16 %
// slower.
inline WalkLimits camera_walk_limits(const PathSettings& s) {
  return {s.max_depth < 0 ? kLongestWalk : s.max_depth, {s.rr_depth, s.rr_max_survival, s.rr_threshold}};
}
inline WalkLimits light_walk_limits(const PathSettings& s) {
  return {s.max_depth < 0 ? kLongestWalk - 1 : std::max<int64_t>(0, s.max_depth - 1),
          {s.rr_depth, s.rr_max_survival, std::numeric_limits<float>::infinity()}};
}

}  // namespace caustica
