#include "integrators/photon/photon_map.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <stdexcept>

namespace caustica {

void PhotonMap::build(std::span<const Photon> photons, float radius) {
  if (!(radius > 0)) throw std::invalid_argument("photon map radius must be positive");
  radius_ = radius;
  inv_cell_ = 1 / radius;
  const size_t n = photons.size();
  const uint32_t buckets = std::bit_ceil(uint32_t(std::max<size_t>(2 * n, 1)));
  mask_ = buckets - 1;
  // A stable counting sort by bucket in two passes, each parallel: first
  // into ranges of buckets (the high bits), chunk by chunk of photons, then
  // within each range. Every step keeps the photons' order, so the map
  // (and every sum over it) is the same for any thread count.
  const uint32_t ranges = std::min<uint32_t>(buckets, kRanges);
  const int shift = std::countr_zero(buckets / ranges);
  const size_t chunks = std::max<size_t>(1, (n + kChunk - 1) / kChunk);
  bucket_of_.resize(n);
  range_counts_.assign(chunks * ranges, 0);
  tbb::parallel_for(size_t(0), chunks, [&](size_t c) {
    uint32_t* counts = &range_counts_[c * ranges];
    for (size_t i = c * kChunk; i < std::min(n, (c + 1) * kChunk); ++i) {
      const Vec3& p = photons[i].p;
      bucket_of_[i] = bucket(cell(p.x), cell(p.y), cell(p.z));
      ++counts[bucket_of_[i] >> shift];
    }
  });
  // Where each chunk's photons of each range go: ranges in order, and
  // within a range the chunks in order.
  range_start_.assign(ranges + 1, 0);
  uint32_t offset = 0;
  for (uint32_t r = 0; r < ranges; ++r) {
    range_start_[r] = offset;
    for (size_t c = 0; c < chunks; ++c) {
      const uint32_t count = range_counts_[c * ranges + r];
      range_counts_[c * ranges + r] = offset;
      offset += count;
    }
  }
  range_start_[ranges] = offset;
  by_range_.resize(n);
  tbb::parallel_for(size_t(0), chunks, [&](size_t c) {
    uint32_t* next = &range_counts_[c * ranges];
    for (size_t i = c * kChunk; i < std::min(n, (c + 1) * kChunk); ++i)
      by_range_[next[bucket_of_[i] >> shift]++] = uint32_t(i);
  });
  start_.resize(size_t(buckets) + 1);
  start_[buckets] = uint32_t(n);
  photons_.resize(n);
  positions_.resize(n);
  tbb::parallel_for(uint32_t(0), ranges, [&](uint32_t r) {
    const uint32_t first_bucket = r << shift, width = uint32_t(1) << shift;
    uint32_t* start = &start_[first_bucket];
    std::fill_n(start, width, 0);
    const uint32_t begin = range_start_[r], end = range_start_[r + 1];
    for (uint32_t k = begin; k < end; ++k) ++start[bucket_of_[by_range_[k]] - first_bucket];
    uint32_t at = begin;
    for (uint32_t b = 0; b < width; ++b) {
      const uint32_t count = start[b];
      start[b] = at;
      at += count;
    }
    // start[b] moves to the bucket's end while photons arrive, then back.
    for (uint32_t k = begin; k < end; ++k) {
      const uint32_t i = by_range_[k];
      const uint32_t to = start[bucket_of_[i] - first_bucket]++;
      photons_[to] = photons[i];
      positions_[to] = photons[i].p;
    }
    for (uint32_t b = width; b-- > 1;) start[b] = start[b - 1];
    start[0] = begin;
  });
}

}  // namespace caustica
