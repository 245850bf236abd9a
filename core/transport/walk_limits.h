#pragma once

#include <cstdint>

#include "core/transport/russian_roulette.h"

namespace caustica {

// How far a walk may go.
struct WalkLimits {
  // Segments from the walk's origin to its last vertex; -1 for no limit.
  // At a vertex this many segments out nothing is sampled any more.
  int64_t max_segments = -1;
  RussianRoulette roulette;
};

}  // namespace caustica
