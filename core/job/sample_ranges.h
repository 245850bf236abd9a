#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace caustica {

// A range of sample indices: [first, first + count).
struct IndexRange {
  uint64_t first = 0, count = 0;
};

// The ranges in order of their first index, empty ones dropped and those
// that touch joined.
std::vector<IndexRange> joined_ranges(std::vector<IndexRange> ranges);

// "first-last,first-last,..." (inclusive), as the caustica:ranges metadata
// lists them.
std::string format_ranges(const std::vector<IndexRange>& ranges);

}  // namespace caustica
