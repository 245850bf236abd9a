#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
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
};

// Photons in a hashed uniform grid whose cells are as wide as the query
// radius, so that a query visits the 27 cells around its point. The table
// has twice as many buckets as photons; cells that share a bucket are
// separated by the distance test, and a bucket is visited once per query.
class PhotonMap {
 public:
  PhotonMap() = default;
  PhotonMap(std::vector<Photon> photons, float radius);

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
    const int cx = cell(p.x), cy = cell(p.y), cz = cell(p.z);
    uint32_t visited[27];
    int n_visited = 0;
    const float r2 = r * r;
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const uint32_t b = bucket(cx + dx, cy + dy, cz + dz);
          bool seen = false;
          for (int i = 0; i < n_visited; ++i) seen = seen || visited[i] == b;
          if (seen) continue;
          visited[n_visited++] = b;
          for (uint32_t i = start_[b]; i < start_[b + 1]; ++i)
            if (squared_length(photons_[i].p - p) <= r2) f(photons_[i]);
        }
  }

 private:
  // Clamped so that a vanishing radius cannot overflow the cell index.
  int cell(float x) const { return int(std::clamp(std::floor(x * inv_cell_), -1e9f, 1e9f)); }
  uint32_t bucket(int x, int y, int z) const {
    // Large primes spread neighbouring cells over the table.
    const uint32_t h = uint32_t(x) * 73856093u ^ uint32_t(y) * 19349663u ^ uint32_t(z) * 83492791u;
    return h & mask_;
  }

  std::vector<Photon> photons_;  // grouped by bucket
  std::vector<uint32_t> start_;  // photons of bucket b: [start_[b], start_[b + 1])
  float radius_ = 0, inv_cell_ = 0;
  uint32_t mask_ = 0;
};

}  // namespace caustica
