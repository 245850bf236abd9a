#include "core/render/renderer.h"

#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>

#include "core/render/pass_schedule.h"

namespace caustica {

RenderStats render(const Scene& scene, const Integrator& integrator, const RenderOptions& options, FilmBuffer& film,
                   RenderProgress* progress) {
  integrator.check_scene(scene);
  const int threads = options.threads > 0 ? options.threads : tbb::this_task_arena::max_concurrency();
  tbb::task_arena arena(threads);
  const bool timed = options.time_limit > 0;
  const uint32_t target = timed ? 0 : (options.spp > 0 ? options.spp : scene.sensor().sampler()->sample_count());
  const uint64_t rays_before = scene.rays_traced();
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };

  if (progress) progress->pixel_samples_target = uint64_t(target) * film.width() * film.height();
  std::unique_ptr<IntegratorRun> run;
  arena.execute([&] { run = integrator.start(scene, options.seed); });
  const uint32_t max_pass = std::max(1u, run->max_pass_samples());
  const PassTarget out{film, progress, threads, options.stop};
  uint32_t done = 0;
  double last_pass = 0;
  uint64_t last_count = 1;
  const auto stopped = [&] { return options.stop && options.stop->load(); };
  // The first pass always runs, so even an early stop leaves an image.
  while (done == 0 || (timed ? !stopped() : done < target && !stopped())) {
    const uint64_t next = options.first_sample + done;
    const Pass pass = pass_containing(next, max_pass);
    // A pass costs about the last one scaled by its share of samples.
    const uint64_t available = pass.first + pass.count - next;
    if (timed && done > 0 && elapsed() + last_pass * double(available) / double(last_count) >= options.time_limit)
      break;
    const uint32_t count = uint32_t(timed ? available : std::min<uint64_t>(available, target - done));
    const double pass_start = elapsed();
    bool completed = false;
    arena.execute([&] { completed = run->run_pass({pass.number, next, count}, out); });
    if (!completed) break;
    done += count;
    last_pass = elapsed() - pass_start;
    last_count = count;
    if (progress) progress->rays = scene.rays_traced() - rays_before;
  }

  arena.execute([&] { run->finish(film); });
  RenderStats stats;
  stats.seconds = elapsed();
  stats.spp = done;
  stats.samples = uint64_t(done) * film.width() * film.height();
  stats.rays = scene.rays_traced() - rays_before;
  stats.dropped = film.dropped_samples();
  stats.first_dropped = film.first_dropped();
  stats.interrupted = stopped() && (timed || done < target);
  stats.variance_known = run->variance_known();
  stats.summary = run->summary();
  return stats;
}

ReplayedSample replay_sample(const Scene& scene, const Integrator& integrator, Vec2i pixel, uint64_t index,
                             uint64_t seed) {
  integrator.check_scene(scene);
  return integrator.start(scene, seed)->replay(pixel, index);
}

}  // namespace caustica
