#pragma once

#include <span>
#include <string>
#include <vector>

#include "core/film/film_buffer.h"
#include "core/film/splat_list.h"
#include "core/geometry/ray.h"
#include "core/registry/plugin.h"
#include "core/sampling/sampler.h"

namespace caustica {

class Scene;

// An estimator of the pixel measurement. Each camera sample writes its
// estimate for its own pixel; integrators that trace light from the
// emitters (ptracer, bdpt) also add splats for wherever their connections to
// the camera land.
class Integrator : public Plugin {
 public:
  // Work that precedes the pixels.
  virtual void prepare(const Scene&) {}
  // Called before each pass over the pixels (the `pass`-th, from 0), e.g. to
  // trace a progressive round of photons; `seed` is the render's.
  virtual void begin_pass(const Scene&, uint32_t /*pass*/, uint64_t /*seed*/) {}
  // The most samples per pixel one pass may hold: progressive methods that
  // refine between passes ask for few.
  virtual uint32_t max_pass_samples() const { return 16; }
  // Called once the passes are done: integrators that keep state per pixel
  // rather than averaging samples put their image into the film here.
  virtual void finish(const Scene&, FilmBuffer&) const {}
  // What it will do with this scene and what it skips as the scene does not
  // need it, in a line or two; for `caustica info` and the render log.
  virtual std::string plan(const Scene&) const { return ""; }
  // Names of the values sample() writes, in order; "R", "G", "B" for radiance.
  virtual std::vector<std::string> channels() const { return {"R", "G", "B"}; }
  // Whether sample() adds splats; the renderer then keeps a splat image.
  virtual bool splats() const { return false; }
  // Estimates the channels along one camera ray. Splats carry the same
  // normalisation as `out`: the film divides their sum by the number of
  // samples per pixel.
  virtual void sample(const Scene& scene, const Ray& ray, Sampler& sampler, std::span<float> out,
                      SplatList& splats) const = 0;
  // Parameters as written back into the output's metadata.
  virtual std::string describe() const = 0;
};

}  // namespace caustica
