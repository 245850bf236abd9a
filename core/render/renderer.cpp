#include "core/render/renderer.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>

#include "core/render/aov_evaluator.h"
#include "core/render/camera_sample.h"

namespace caustica {

namespace {

constexpr int kTileSize = 16;

struct Tile {
  Vec2i lo, hi;
};

std::vector<Tile> make_tiles(int width, int height) {
  std::vector<Tile> tiles;
  for (int y = 0; y < height; y += kTileSize)
    for (int x = 0; x < width; x += kTileSize)
      tiles.push_back({{x, y}, {std::min(x + kTileSize, width), std::min(y + kTileSize, height)}});
  return tiles;
}

const AovEvaluator& standard_aovs() {
  static const AovEvaluator evaluator(parse_aov_list("albedo:albedo,normal:sh_normal,depth:depth"));
  return evaluator;
}

// Everything one sample needs; `values` is scratch space of channel size.
CameraSample run_sample(const Scene& scene, Sampler& sampler, Vec2i pixel, uint64_t index, uint64_t seed,
                        std::span<float> values, SplatList& splats) {
  splats.set_source({pixel, index});
  const CameraSample cs = sample_camera_ray(scene, sampler, pixel, index, seed);
  scene.integrator()->sample(scene, cs.ray, sampler, values, splats);
  return cs;
}

struct ThreadState {
  std::unique_ptr<Sampler> sampler;
  std::vector<float> values, aov_values;
  SplatList unused_splats;  // for integrators that make none
};

struct PassSettings {
  uint32_t first, count;
  uint64_t seed;
};

void render_tile(const Scene& scene, const Tile& tile, const PassSettings& pass, ThreadState& state, SplatList& splats,
                 FilmBuffer& film, FilmBuffer* aovs, RenderProgress* progress) {
  for (int y = tile.lo.y; y < tile.hi.y; ++y)
    for (int x = tile.lo.x; x < tile.hi.x; ++x)
      for (uint32_t i = pass.first; i < pass.first + pass.count; ++i) {
        const CameraSample cs = run_sample(scene, *state.sampler, {x, y}, i, pass.seed, state.values, splats);
        film.add_sample({{x, y}, i}, state.values, cs.weight);
        if (aovs && i < kAovSamples) {
          standard_aovs().evaluate(scene, cs.ray, state.aov_values);
          aovs->add_sample({{x, y}, i}, state.aov_values, cs.weight);
        }
      }
  if (progress) progress->pixel_samples += uint64_t(pass.count) * (tile.hi.x - tile.lo.x) * (tile.hi.y - tile.lo.y);
}

// Splatting integrators render the tiles in chunks: each tile collects its
// splats in its own list, then the lists enter the film in tile order, in
// parallel over bands of rows. Every pixel thus receives its splats in the
// same order for any thread count, and memory stays bounded by the chunk.
void render_pass(const Scene& scene, const std::vector<Tile>& tiles, const PassSettings& pass, int threads,
                 FilmBuffer& film, FilmBuffer* aovs, RenderProgress* progress) {
  tbb::enumerable_thread_specific<ThreadState> states([&] {
    return ThreadState{scene.sensor().sampler()->clone(),
                       std::vector<float>(film.channel_count()),
                       std::vector<float>(aovs ? aovs->channel_count() : 0),
                       {}};
  });
  if (!scene.integrator()->splats()) {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, tiles.size(), 1), [&](const tbb::blocked_range<size_t>& range) {
      ThreadState& state = states.local();
      for (size_t t = range.begin(); t != range.end(); ++t)
        render_tile(scene, tiles[t], pass, state, state.unused_splats, film, aovs, progress);
    });
    return;
  }
  const size_t chunk = std::max<size_t>(8, 4 * size_t(threads));
  std::vector<SplatList> lists(std::min(chunk, tiles.size()));
  const ReconstructionFilter& filter = scene.sensor().film()->filter();
  for (size_t begin = 0; begin < tiles.size(); begin += chunk) {
    const size_t end = std::min(begin + chunk, tiles.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(begin, end, 1), [&](const tbb::blocked_range<size_t>& range) {
      ThreadState& state = states.local();
      for (size_t t = range.begin(); t != range.end(); ++t) {
        lists[t - begin].clear();
        render_tile(scene, tiles[t], pass, state, lists[t - begin], film, aovs, progress);
      }
    });
    tbb::parallel_for(tbb::blocked_range<int>(0, film.height(), kTileSize), [&](const tbb::blocked_range<int>& rows) {
      for (size_t i = 0; i < end - begin; ++i) film.add_splats(lists[i], filter, rows.begin(), rows.end());
    });
    for (size_t i = 0; i < end - begin; ++i) film.record_dropped(lists[i]);
  }
}

}  // namespace

std::vector<std::string> standard_aov_channels() { return standard_aovs().channels(); }

RenderStats render(const Scene& scene, const RenderOptions& options, FilmBuffer& film, FilmBuffer* aovs,
                   RenderProgress* progress) {
  const int threads = options.threads > 0 ? options.threads : tbb::this_task_arena::max_concurrency();
  tbb::task_arena arena(threads);
  const auto tiles = make_tiles(film.width(), film.height());
  const bool timed = options.time_limit > 0;
  const uint32_t target = timed ? 0 : (options.spp > 0 ? options.spp : scene.sensor().sampler()->sample_count());
  const uint64_t rays_before = scene.rays_traced();
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };

  if (progress) progress->pixel_samples_target = uint64_t(target) * film.width() * film.height();
  scene.integrator()->prepare(scene);
  if (scene.integrator()->splats()) film.enable_splats();
  const uint32_t max_pass = std::max(1u, scene.integrator()->max_pass_samples());
  uint32_t done = 0, passes = 0;
  double last_pass = 0;
  // Small passes at first so progress and time budgets react quickly.
  uint32_t pass = 1;
  // A pass costs about last_pass scaled by its share of samples.
  uint32_t last_count = 1;
  const auto stopped = [&] { return options.stop && options.stop->load(); };
  // The first pass always runs, so even an early stop leaves an image.
  while (timed ? (elapsed() + last_pass * pass / last_count < options.time_limit && !stopped()) || done == 0
               : done < target && (!stopped() || done == 0)) {
    const uint32_t count = timed ? pass : std::min(pass, target - done);
    const double pass_start = elapsed();
    arena.execute([&] {
      scene.integrator()->begin_pass(scene, passes++, options.seed);
      render_pass(scene, tiles, {done, count, options.seed}, threads, film, aovs, progress);
    });
    done += count;
    film.set_splat_paths_per_pixel(done);
    last_pass = elapsed() - pass_start;
    last_count = count;
    pass = std::min<uint32_t>(pass * 2, max_pass);
    if (progress) progress->rays = scene.rays_traced() - rays_before;
  }

  scene.integrator()->finish(scene, film);
  RenderStats stats;
  stats.seconds = elapsed();
  stats.spp = done;
  stats.samples = uint64_t(done) * film.width() * film.height();
  stats.rays = scene.rays_traced() - rays_before;
  stats.dropped = film.dropped_samples();
  stats.first_dropped = film.first_dropped();
  stats.interrupted = stopped() && (timed || done < target);
  return stats;
}

ReplayedSample replay_sample(const Scene& scene, Vec2i pixel, uint64_t index, uint64_t seed) {
  // The integrator is set up as the render had it for the pass holding the sample.
  scene.integrator()->prepare(scene);
  const uint32_t max_pass = std::max(1u, scene.integrator()->max_pass_samples());
  uint32_t pass = 0;
  for (uint64_t first = 0, size = 1; first + size <= index;
       first += size, size = std::min<uint64_t>(size * 2, max_pass))
    ++pass;
  scene.integrator()->begin_pass(scene, pass, seed);
  auto sampler = scene.sensor().sampler()->clone();
  ReplayedSample out{std::vector<float>(scene.integrator()->channels().size()), {}};
  run_sample(scene, *sampler, pixel, index, seed, out.values, out.splats);
  return out;
}

}  // namespace caustica
