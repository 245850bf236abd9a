#pragma once

#include <algorithm>
#include <cstdint>

namespace caustica {

// The passes every render is cut into, a pure function of the sample index:
// pass 0 holds sample 0, pass 1 samples 1-2, pass 2 samples 3-6, ...
// doubling up to `max_pass` samples a pass, then `max_pass` each. Small
// passes first let progress and time budgets react quickly. Progressive
// integrators refine between passes (a new photon round per pass), so a
// sample's pass, and with it its value, does not depend on where a render
// of a range of samples began: disjoint ranges merge into the image of one
// render of their union.
struct Pass {
  uint32_t number;
  uint64_t first, count;
};

inline Pass pass_containing(uint64_t index, uint32_t max_pass) {
  max_pass = std::max(1u, max_pass);
  uint64_t first = 0, size = 1;
  uint32_t number = 0;
  while (size < max_pass && first + size <= index) {
    first += size;
    size *= 2;
    ++number;
  }
  size = std::min<uint64_t>(size, max_pass);
  if (index >= first + size) {
    const uint64_t skipped = (index - first) / size;
    first += skipped * size;
    number += uint32_t(skipped);
  }
  return {number, first, size};
}

}  // namespace caustica
