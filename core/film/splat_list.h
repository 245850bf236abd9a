#pragma once

#include <cstdint>
#include <vector>

#include "core/film/film_buffer.h"
#include "core/math/color.h"
#include "core/math/vec.h"

namespace caustica {

// A contribution that lands anywhere on the film rather than on the pixel
// whose sample made it (light tracing connects to the camera wherever the
// connection falls).
struct Splat {
  Vec2 raster;
  uint32_t channel;  // first of the three channels it adds to
  Color value;
};

// The splats of a run of samples, kept in the order they were made so that
// the film can add them in a fixed order whatever thread made them. Like the
// film, it drops non-finite values and remembers which sample made them.
// Threads fill lists that lie side by side; a cache line each keeps them
// from writing to one another's.
class alignas(64) SplatList {
 public:
  // The sample whose splats follow, for reporting a dropped one.
  void set_source(SampleId id) { source_ = id; }
  void add(Vec2 raster, Color value, uint32_t channel = 0) {
    if (!value.is_finite()) {
      if (dropped_ == 0) first_dropped_ = source_;
      ++dropped_;
      return;
    }
    if (!value.is_black()) splats_.push_back({raster, channel, value});
  }
  void clear() {
    splats_.clear();
    dropped_ = 0;
  }

  const std::vector<Splat>& splats() const { return splats_; }
  uint64_t dropped() const { return dropped_; }
  SampleId first_dropped() const { return first_dropped_; }

 private:
  std::vector<Splat> splats_;
  SampleId source_, first_dropped_;
  uint64_t dropped_ = 0;
};

}  // namespace caustica
