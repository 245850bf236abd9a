#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "core/film/film_buffer.h"
#include "core/scene/scene.h"

namespace caustica {

struct RenderOptions {
  uint32_t spp = 0;       // 0: the scene sampler's sample_count
  double time_limit = 0;  // seconds; when positive, render passes until it is spent
  uint64_t seed = 0;
  int threads = 0;  // 0: all cores
};

struct RenderProgress {
  uint32_t spp_done = 0, spp_target = 0;  // target 0 when rendering for a time budget
  double seconds = 0;
  uint64_t rays = 0;
};

struct RenderStats {
  double seconds = 0;
  uint32_t spp = 0;
  uint64_t samples = 0, rays = 0;
  uint64_t dropped = 0;
  SampleId first_dropped;
};

// Renders the scene's integrator over the whole film in passes of whole
// samples per pixel, tiles in parallel. Pixel p's sample i always uses the
// random numbers keyed by (seed, p, i) and enters the film in index order,
// so the image is bit-identical for any thread count.
RenderStats render(const Scene& scene, const RenderOptions& options, FilmBuffer& film,
                   const std::function<void(const RenderProgress&)>& on_pass = {});

// Runs one sample alone and returns the channel values before they reach
// the film: a sample replayed under a debugger takes exactly this path.
std::vector<float> replay_sample(const Scene& scene, Vec2i pixel, uint64_t index, uint64_t seed);

}  // namespace caustica
