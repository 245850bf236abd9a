#pragma once

#include <atomic>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/film/film_buffer.h"
#include "core/film/splat_list.h"
#include "core/scene/scene.h"

namespace caustica {

struct RenderOptions {
  uint32_t spp = 0;       // 0: the scene sampler's sample_count
  double time_limit = 0;  // seconds; when positive, render passes until it is spent
  uint64_t seed = 0;
  int threads = 0;  // 0: all cores
  // Checked between passes: once it is true the render stops there (after
  // the first pass at the earliest), with every pixel holding the same whole
  // number of samples.
  const std::atomic<bool>* stop = nullptr;
};

// The first-hit layers written beside the beauty (albedo, shading normal,
// depth). They are estimated from the first kAovSamples samples of each
// pixel only: noise-free values converge within a few samples, and the
// extra ray per sample then costs nothing at high sample counts.
inline constexpr uint32_t kAovSamples = 16;
std::vector<std::string> standard_aov_channels();

// Shared with a progress display while a render runs.
struct RenderProgress {
  std::atomic<uint64_t> pixel_samples{0};         // updated after every tile
  std::atomic<uint64_t> rays{0};                  // updated after every pass
  std::atomic<uint64_t> pixel_samples_target{0};  // 0 when rendering for a time budget
};

struct RenderStats {
  double seconds = 0;
  uint32_t spp = 0;
  uint64_t samples = 0, rays = 0;
  uint64_t dropped = 0;
  SampleId first_dropped;
  bool interrupted = false;
};

// Renders the scene's integrator over the whole film in passes of whole
// samples per pixel, tiles in parallel. Pixel p's sample i always uses the
// random numbers keyed by (seed, p, i) and enters the film in index order,
// so the image is bit-identical for any thread count. `aovs`, if given,
// receives the standard_aov_channels().
RenderStats render(const Scene& scene, const RenderOptions& options, FilmBuffer& film, FilmBuffer* aovs = nullptr,
                   RenderProgress* progress = nullptr);

// One sample's output before it reaches the film.
struct ReplayedSample {
  std::vector<float> values;
  SplatList splats;
};

// Runs one sample alone: a sample replayed under a debugger takes exactly
// the path it took in the render.
ReplayedSample replay_sample(const Scene& scene, Vec2i pixel, uint64_t index, uint64_t seed);

}  // namespace caustica
