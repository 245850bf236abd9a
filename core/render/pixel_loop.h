#pragma once

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/render/camera_sample.h"
#include "core/render/sample_scratch.h"
#include "core/render/tiles.h"

namespace caustica {

// Runs fn(pixel, index, camera_sample, scratch) for samples [first, first +
// count) of every pixel of `tiles`, tiles in parallel and each pixel's
// samples in index order, then tile_done(tile). Once `stop` (may be null)
// turns true it starts no more tiles, and returns false. A `time` fixes
// every camera ray's (see sample_camera_ray).
template <class Fn, class TileDone>
bool for_each_camera_sample(const Scene& scene, uint64_t seed, const std::vector<Tile>& tiles, uint64_t first,
                            uint64_t count, size_t channels, const std::atomic<bool>* stop, std::optional<float> time,
                            Fn&& fn, TileDone&& tile_done) {
  tbb::enumerable_thread_specific<SampleScratch> scratch([&] { return SampleScratch(scene, channels); });
  std::atomic<bool> stopped{false};
  tbb::parallel_for(tbb::blocked_range<size_t>(0, tiles.size(), 1), [&](const tbb::blocked_range<size_t>& r) {
    SampleScratch& s = scratch.local();
    for (size_t t = r.begin(); t != r.end(); ++t) {
      if (stop && stop->load()) {
        stopped = true;
        return;
      }
      const Tile& tile = tiles[t];
      for (int y = tile.lo.y; y < tile.hi.y; ++y)
        for (int x = tile.lo.x; x < tile.hi.x; ++x)
          for (uint64_t i = first; i < first + count; ++i)
            fn(Vec2i{x, y}, i, sample_camera_ray(scene, *s.sampler, {x, y}, i, seed, time), s);
      tile_done(tile);
    }
  });
  return !stopped;
}

}  // namespace caustica
