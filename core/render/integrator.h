#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/film/film_buffer.h"
#include "core/film/splat_list.h"
#include "core/registry/plugin.h"

namespace caustica {

class Scene;
struct RenderProgress;

// What one pass of a render covers: sample indices [first, first + count)
// of every pixel (iterations, for iterative integrators), all within pass
// number `pass` of the schedule (core/render/pass_schedule.h).
struct PassRange {
  uint32_t pass = 0;
  uint64_t first = 0;
  uint32_t count = 0;
};

// Where a pass's values go and what it may use.
struct PassTarget {
  FilmBuffer& film;
  RenderProgress* progress;
  int threads;
  // Polled by passes that trace photons, which can take long before any
  // sample reaches the film: once it is true they stop and add nothing.
  const std::atomic<bool>* stop = nullptr;
};

// One sample's output before it reaches the film, for replaying it alone.
struct ReplayedSample {
  std::vector<float> values;
  SplatList splats;
};

// The state of one render of an integrator over one scene, made for that
// render (so a loaded scene and its integrator stay const, and two renders
// of one scene can run at once), with its family's loop.
class IntegratorRun {
 public:
  virtual ~IntegratorRun() = default;
  // The most samples per pixel (or iterations) one pass may hold:
  // progressive methods that refine between passes ask for few.
  virtual uint32_t max_pass_samples() const { return 16; }
  // Returns false when target.stop ended the pass before it added anything.
  virtual bool run_pass(PassRange range, const PassTarget& target) = 0;
  // Called once the passes are done.
  virtual void finish(FilmBuffer&) {}
  // Whether the film's per-pixel variance describes the estimate: not where
  // a pixel's light comes from other pixels' samples or from state kept
  // across iterations.
  virtual bool variance_known() const { return true; }
  // Runs sample `index` of `pixel` alone, as the render ran it.
  virtual ReplayedSample replay(Vec2i pixel, uint64_t index) = 0;
  // What this render did that the integrator's parameters do not say
  // ("rounds=12", "photon pass skipped"), for the metadata; may be empty.
  virtual std::string summary() const { return ""; }
};

// A named light-transport algorithm. It belongs to one of three families,
// each with its own loop (core/render/{pixel,light_path,iterative}_integrator.h):
// per-pixel estimators, light-path integrators that splat, and iterative
// density estimators. Every value reaches the film through
// FilmBuffer::add_sample or a SplatList, which drop and count non-finite
// values.
class Integrator : public Plugin {
 public:
  // Names of the values a sample writes, in order; "R", "G", "B" for radiance.
  virtual std::vector<std::string> channels() const { return {"R", "G", "B"}; }
  // What it will do with this scene and what it skips as the scene does not
  // need it, in a line or two; for `caustica info` and the render log.
  virtual std::string plan(const Scene&) const { return ""; }
  // Whether the samples of a pass may be rendered apart, a range of them by
  // another process, their films then added: not where iterations share
  // per-pixel state.
  virtual bool splits_samples() const { return true; }
  // What a render across several processes does that the plan should say.
  virtual std::string distributed_note() const { return ""; }
  // Whether it follows paths through participating media and null surfaces.
  virtual bool renders_media() const { return false; }
  // Whether its paths follow a time through the shutter (every ray of a
  // path, and every path it joins, at one time), so that it renders moving
  // shapes, lights and cameras.
  virtual bool renders_motion() const { return false; }
  // Whether it renders in spectral mode (paths carrying wavelengths).
  virtual bool renders_spectral() const { return false; }
  // Whether it traces all of its light from the lights, so that it sees
  // lights only light paths can (directionalarea).
  virtual bool traces_all_light_from_lights() const { return false; }
  // Throws std::invalid_argument, saying why, if it cannot render `scene`
  // (a scene with media or moving shapes for an integrator that does not
  // render them, or a
  // scene in spectral mode that it or the scene's materials cannot render
  // so yet).
  void check_scene(const Scene& scene) const;
  // Its name and parameters, for the output's metadata.
  std::string describe() const { return describe_parameters(); }
  // Starts a render of `scene` with the render's seed.
  virtual std::unique_ptr<IntegratorRun> start(const Scene& scene, uint64_t seed) const = 0;
};

}  // namespace caustica
