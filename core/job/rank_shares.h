#pragma once

#include <cstdint>

#include "core/job/sample_ranges.h"

namespace caustica {

// Rank `rank`'s share of `range` among `ranks` ranks: the ranks take
// contiguous pieces in rank order, of sizes differing by at most one; the
// larger pieces go to ranks that rotate with `round`, so that over `ranks`
// rounds of equal size every rank renders as many samples.
inline IndexRange rank_share(IndexRange range, int rank, int ranks, uint64_t round) {
  const uint64_t n = uint64_t(ranks), base = range.count / n, extra = range.count % n;
  // The ranks holding an extra sample are (round + j) mod n for j < extra.
  const auto holds_extra = [&](uint64_t r) { return (r + n - round % n) % n < extra; };
  uint64_t first = range.first;
  for (uint64_t r = 0; r < uint64_t(rank); ++r) first += base + (holds_extra(r) ? 1 : 0);
  return {first, base + (holds_extra(uint64_t(rank)) ? 1 : 0)};
}

}  // namespace caustica
