#include "core/job/sample_ranges.h"

#include <algorithm>

namespace caustica {

std::vector<IndexRange> joined_ranges(std::vector<IndexRange> ranges) {
  std::stable_sort(ranges.begin(), ranges.end(), [](IndexRange a, IndexRange b) { return a.first < b.first; });
  std::vector<IndexRange> joined;
  for (IndexRange r : ranges) {
    if (r.count == 0) continue;
    if (!joined.empty() && joined.back().first + joined.back().count == r.first)
      joined.back().count += r.count;
    else
      joined.push_back(r);
  }
  return joined;
}

std::string format_ranges(const std::vector<IndexRange>& ranges) {
  std::string text;
  for (IndexRange r : ranges) {
    if (!text.empty()) text.append(",");
    text.append(std::to_string(r.first)).append("-").append(std::to_string(r.first + r.count - 1));
  }
  return text;
}

}  // namespace caustica
