#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "core/film/film_buffer.h"
#include "core/loader/scene_loader.h"
#include "core/render/first_hit_layers.h"
#include "core/render/renderer.h"

namespace caustica {

// How a scene is rendered: everything that is not the scene itself.
// The most worker threads a render takes.
inline constexpr int kMaxThreads = 1024;
// Sample indices stay below 2^62, so that a first sample plus any count of
// samples (at most 2^31 per pixel and pass) never wraps.
inline constexpr uint64_t kMaxFirstSample = uint64_t(1) << 62;

struct RenderSettings {
  // NAME or NAME:param=value,... to replace the scene's integrator; the
  // scene's integrator parameters that NAME shares stay unless named.
  std::string integrator;
  uint32_t spp = 0;           // 0: the scene sampler's sample_count
  uint64_t first_sample = 0;  // render sample indices first_sample, first_sample + 1, ...
  double time_limit = 0;      // seconds; when positive, instead of spp
  uint64_t seed = 0;
  int threads = 0;   // 0: all cores
  bool aovs = true;  // the first-hit layers, for integrators of radiance (FirstHitLayers)
  // Spectral or RGB transport: as the scene analysis decides, or forced
  // (which rewrites the loaded scene's analysis, for every job sharing it).
  enum class Transport { AsTheSceneNeeds, Rgb, Spectral } transport = Transport::AsTheSceneNeeds;
  // How points to be lit choose their light: as the scene analysis decides
  // (the light tree for two emitters or more it can bound), or forced, as
  // transport is.
  enum class LightSelection { AsTheSceneNeeds, Power, Tree } light_selection = LightSelection::AsTheSceneNeeds;
  const std::atomic<bool>* stop = nullptr;
};

// What a render made: its film and its report.
struct RenderResult {
  FilmBuffer film;
  RenderStats stats;
};

// The one way caustica renders, for the command line, the benchmarks and
// the tests alike: a loaded scene (analysed at load), the integrator the
// settings call for, and run() rendering a range of samples into a fresh
// film. The scene and the integrator stay const, so one job may run
// several times, even at once.
class RenderJob {
 public:
  RenderJob(LoadedScene scene, RenderSettings settings);

  const LoadedScene& scene() const { return scene_; }
  const Integrator& integrator() const { return *integrator_; }
  const RenderSettings& settings() const { return settings_; }
  // What the integrator will do with this scene, and what it skips.
  // What the integrator will do with the scene, and the transport mode where worth saying.
  std::string plan() const;

  RenderResult run(RenderProgress* progress = nullptr) const;
  // The first-hit layers of a result of run(), to be evaluated as its image
  // is written; none unless the settings ask for them and the integrator
  // renders radiance. They refer to the job and to `result`.
  std::optional<FirstHitLayers> first_hit_layers(const RenderResult& result) const;
  // Runs one sample alone, as run() renders it.
  ReplayedSample replay(Vec2i pixel, uint64_t index) const;

 private:
  LoadedScene scene_;
  RenderSettings settings_;
  std::shared_ptr<const Integrator> integrator_;
};

// Loads the scene file and makes its job.
RenderJob load_render_job(const std::filesystem::path& file, const Defines& defines, RenderSettings settings);

}  // namespace caustica
