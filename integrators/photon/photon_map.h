#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "core/math/color.h"
#include "core/math/vec.h"

namespace caustica {

// Light stored where it landed on a surface.
struct Photon {
  Vec3 p;
  Vec3 wi;             // unit direction toward where it came from
  Vec3 n;              // geometric normal of the surface it landed on
  Color power;         // flux it carries, before division by the photons emitted
  uint32_t depth = 0;  // segments from the light
  // In spectral mode: it met a dispersive surface, so only the hero
  // wavelength's power counts (the others are zero).
  bool hero_only = false;
  // vcm: which stored light-subpath vertex the photon stands for.
  uint32_t source = 0;
};

// Photons in a hashed uniform grid whose cells are as wide as the query
// radius. A query visits the cells its sphere reaches (3 along each axis,
// about 21 of the 27 around it), skipping empty buckets before the check
// for a bucket seen before; finer cells scan less space but cost more in
// cells visited and cache misses (photon_lookup_benchmark). The table has
// twice as many buckets as photons; cells that share a bucket are separated
// by the distance test, and a bucket is visited once per query.
class PhotonMap {
 public:
  PhotonMap() = default;
  PhotonMap(std::span<const Photon> photons, float radius) { build(photons, radius); }
  // Replaces the map's photons, reusing its memory.
  void build(std::span<const Photon> photons, float radius);

  float radius() const { return radius_; }
  size_t size() const { return photons_.size(); }
  bool empty() const { return photons_.empty(); }

  // Calls f(photon) for every photon within the radius of p.
  template <class F>
  void for_each_within(Vec3 p, F&& f) const {
    for_each_within(p, radius_, f);
  }
  // The same within r, which must not exceed the map's radius.
  template <class F>
  void for_each_within(Vec3 p, float r, F&& f) const {
    if (photons_.empty()) return;
    // In units of cells, widened by the rounding of p * inv_cell_, so that
    // no cell holding a photon within r is left out. Past 2^19 cells from
    // the origin the widening stops at half a cell (kMaxCells): there a
    // float position is itself uncertain by a sixteenth of a cell.
    const Vec3 u = p * inv_cell_;
    const float reach = r * inv_cell_ * (1 + 1e-6f) + std::min(0x1p-20f * (max_component(abs(u)) + 1), 0.5f);
    const float reach2 = reach * reach;
    const float r2 = r * r;
    uint32_t visited[kMaxCells];
    int n_visited = 0;
    uint64_t maybe_visited[4] = {};  // a bit per bucket number modulo 256
    for (int z = cell_of(u.z - reach), z1 = cell_of(u.z + reach); z <= z1; ++z) {
      const float gz = gap(u.z, z), gz2 = gz * gz;
      if (gz2 > reach2) continue;
      for (int y = cell_of(u.y - reach), y1 = cell_of(u.y + reach); y <= y1; ++y) {
        const float gy = gap(u.y, y), gyz2 = gz2 + gy * gy;
        if (gyz2 > reach2) continue;
        for (int x = cell_of(u.x - reach), x1 = cell_of(u.x + reach); x <= x1; ++x) {
          const float gx = gap(u.x, x);
          if (gyz2 + gx * gx > reach2) continue;
          const uint32_t b = bucket(x, y, z);
          // Only buckets holding photons and sharing a bit with one seen
          // before need the list searched.
          if (start_[b] == start_[b + 1]) continue;
          uint64_t& word = maybe_visited[(b >> 6) & 3];
          const uint64_t bit = uint64_t(1) << (b & 63);
          if (word & bit) {
            bool seen = false;
            for (int i = 0; i < n_visited; ++i) seen = seen || visited[i] == b;
            if (seen) continue;
          }
          word |= bit;
          visited[n_visited++] = b;
          for (uint32_t i = start_[b]; i < start_[b + 1]; ++i)
            if (squared_length(positions_[i] - p) <= r2) f(photons_[i]);
        }
      }
    }
  }

 private:
  // Cells a query reaches along one axis: 2 r / r + 1, and one more for
  // the rounding margin of at most half a cell.
  static constexpr int kMaxCells = 4 * 4 * 4;

  // Clamped so that a vanishing radius cannot overflow the cell index.
  static int cell_of(float u) { return int(std::clamp(std::floor(u), -1e9f, 1e9f)); }
  int cell(float x) const { return cell_of(x * inv_cell_); }
  // How far u lies outside cell c, in cells.
  static float gap(float u, int c) { return std::max({0.0f, float(c) - u, u - float(c + 1)}); }
  uint32_t bucket(int x, int y, int z) const {
    // Large primes spread neighbouring cells over the table.
    const uint32_t h = uint32_t(x) * 73856093u ^ uint32_t(y) * 19349663u ^ uint32_t(z) * 83492791u;
    return h & mask_;
  }

  // build() sorts chunks of kChunk photons into kRanges ranges of buckets
  // in parallel, then each range.
  static constexpr size_t kChunk = 16384;
  static constexpr uint32_t kRanges = 256;

  std::vector<Photon> photons_;  // grouped by bucket
  // The photons' positions again, packed: a query tests the positions of
  // every photon in the cells it visits but reads the rest of few, so the
  // test reads about a fifth of the memory (a query's time is mostly its cache
  // misses).
  std::vector<Vec3> positions_;
  std::vector<uint32_t> start_;  // photons of bucket b: [start_[b], start_[b + 1])
  // Scratch of build(), kept for the next: each photon's bucket, where each
  // chunk's photons of each range go, where each range starts, and the
  // photons' indices sorted by range.
  std::vector<uint32_t> bucket_of_, range_counts_, range_start_, by_range_;
  float radius_ = 0, inv_cell_ = 0;
  uint32_t mask_ = 0;
};

}  // namespace caustica
