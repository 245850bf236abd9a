#pragma once

#include <cstddef>
#include <span>

namespace caustica {

// The index of the first element of the sorted `values` that compares
// greater than x (values.size() if none), as std::upper_bound finds it, but
// halving the range by conditional moves: sampling searches CDFs with
// random targets, where a branch per step is mispredicted half the time.
inline size_t branchless_upper_bound(std::span<const float> values, float x) {
  if (values.empty()) return 0;
  const float* base = values.data();
  size_t len = values.size();
  while (len > 1) {
    const size_t half = len / 2;
    base += x < base[half - 1] ? 0 : half;
    len -= half;
  }
  return size_t(base - values.data()) + (x < *base ? 0 : 1);
}

}  // namespace caustica
