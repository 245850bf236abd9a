#include "core/render/light_path_integrator.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <vector>

#include "core/render/camera_sample.h"
#include "core/render/renderer.h"
#include "core/render/sample_scratch.h"
#include "core/render/tiles.h"
#include "core/scene/scene.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

class LightPathRun final : public IntegratorRun {
 public:
  LightPathRun(const LightPathIntegrator& integrator, const Scene& scene, uint64_t seed)
      : integrator_(integrator),
        scene_(scene),
        seed_(seed),
        channels_(integrator.channels().size()),
        tiles_(make_tiles(scene.sensor().film()->width(), scene.sensor().film()->height())) {}

  bool variance_known() const override { return false; }

  bool run_pass(PassRange range, const PassTarget& target) override {
    target.film.enable_splats();
    tbb::enumerable_thread_specific<SampleScratch> scratch([&] { return SampleScratch(scene_, channels_); });
    // Tiles are rendered a chunk at a time, then their splats added by bands
    // of rows. Chunks of many tiles keep every thread busy up to the barrier
    // (tiles differ in cost); a few bands per thread keep each splat from
    // being tested against many bands it does not reach.
    const size_t chunk = std::max<size_t>(8, 32 * size_t(target.threads));
    const int band = std::max(kTileSize, (target.film.height() + 2 * target.threads - 1) / (2 * target.threads));
    std::vector<SplatList> lists(std::min(chunk, tiles_.size()));
    const ReconstructionFilter& filter = scene_.sensor().film()->filter();
    for (size_t begin = 0; begin < tiles_.size(); begin += chunk) {
      const size_t end = std::min(begin + chunk, tiles_.size());
      tbb::parallel_for(tbb::blocked_range<size_t>(begin, end, 1), [&](const tbb::blocked_range<size_t>& r) {
        SampleScratch& s = scratch.local();
        for (size_t t = r.begin(); t != r.end(); ++t) {
          lists[t - begin].clear();
          render_tile(tiles_[t], range, target, s, lists[t - begin]);
        }
      });
      tbb::parallel_for(tbb::blocked_range<int>(0, target.film.height(), band),
                        [&](const tbb::blocked_range<int>& rows) {
                          for (size_t i = 0; i < end - begin; ++i)
                            target.film.add_splats(lists[i], filter, rows.begin(), rows.end());
                        });
      for (size_t i = 0; i < end - begin; ++i) target.film.record_dropped(lists[i]);
    }
    target.film.add_splat_paths(range.count);
    return true;
  }

  ReplayedSample replay(Vec2i pixel, uint64_t index) override {
    auto sampler = scene_.sensor().sampler()->clone();
    ReplayedSample out{std::vector<float>(channels_), {}};
    out.splats.set_source({pixel, index});
    integrator_.sample(scene_, {pixel, index}, seed_, *sampler, out.values, out.splats);
    return out;
  }

 private:
  void render_tile(const Tile& tile, PassRange range, const PassTarget& target, SampleScratch& s,
                   SplatList& splats) const {
    for (int y = tile.lo.y; y < tile.hi.y; ++y)
      for (int x = tile.lo.x; x < tile.hi.x; ++x)
        for (uint64_t i = range.first; i < range.first + range.count; ++i) {
          const SampleId id{{x, y}, i};
          splats.set_source(id);
          const float weight = integrator_.sample(scene_, id, seed_, *s.sampler, s.values, splats);
          target.film.add_sample(id, s.values, weight);
        }
    if (target.progress) target.progress->pixel_samples += range.count * tile.pixels();
  }

  const LightPathIntegrator& integrator_;
  const Scene& scene_;
  uint64_t seed_;
  size_t channels_;
  std::vector<Tile> tiles_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

std::unique_ptr<IntegratorRun> LightPathIntegrator::start(const Scene& scene, uint64_t seed) const {
  return std::make_unique<LightPathRun>(*this, scene, seed);
}

}  // namespace caustica
