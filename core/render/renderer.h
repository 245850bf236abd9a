#pragma once

#include <atomic>
#include <cstdint>
#include <string>

#include "core/film/film_buffer.h"
#include "core/render/integrator.h"
#include "core/scene/scene.h"

namespace caustica {

struct RenderOptions {
  uint32_t spp = 0;           // 0: the scene sampler's sample_count
  uint64_t first_sample = 0;  // the first sample index rendered
  double time_limit = 0;      // seconds; when positive, render passes until it is spent
  uint64_t seed = 0;
  int threads = 0;  // 0: all cores
  // Checked between passes: once it is true the render stops there (after
  // the first pass at the earliest), with every pixel holding the same whole
  // number of samples.
  const std::atomic<bool>* stop = nullptr;
};

// Shared with a progress display while a render runs.
struct RenderProgress {
  std::atomic<uint64_t> pixel_samples{0};         // updated after every tile
  std::atomic<uint64_t> rays{0};                  // updated after every pass
  std::atomic<uint64_t> pixel_samples_target{0};  // 0 when rendering for a time budget
};

struct RenderStats {
  double seconds = 0;
  uint32_t spp = 0;
  uint64_t samples = 0;
  uint64_t rays = 0;  // traced by the integrator
  uint64_t dropped = 0;
  SampleId first_dropped;
  bool interrupted = false;
  bool variance_known = true;  // whether the film's variance describes the estimate
  std::string summary;         // what the render did beyond its parameters (IntegratorRun::summary)
  int ranks = 1;               // the processes that rendered it (core/job/distributed_render.h)
  // The sample indices held, "first-last,..." where they are not the
  // contiguous spp from the first sample (ranks lost part-way); else empty.
  std::string ranges;
};

// Renders `integrator` over `scene` in passes (core/render/pass_schedule.h)
// of sample indices first_sample, first_sample + 1, ...; the integrator's
// family runs each pass. Sample i of pixel p always uses the random numbers
// keyed by (seed, stream, p, i) and enters the film in index order, so the
// image is bit-identical for any thread count.
RenderStats render(const Scene& scene, const Integrator& integrator, const RenderOptions& options, FilmBuffer& film,
                   RenderProgress* progress = nullptr);

// Runs one sample alone: a sample replayed under a debugger takes exactly
// the path it took in the render.
ReplayedSample replay_sample(const Scene& scene, const Integrator& integrator, Vec2i pixel, uint64_t index,
                             uint64_t seed);

}  // namespace caustica
