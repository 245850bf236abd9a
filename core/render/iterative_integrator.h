#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>

#include "core/math/color.h"
#include "core/render/integrator.h"

namespace caustica {

// The state of one render of an iterative density estimator: what it keeps
// per pixel across iterations.
class IterationState {
 public:
  virtual ~IterationState() = default;
  // Runs iteration number `iteration` over every pixel; false, changing
  // nothing, if `stop` (may be null) turned true before it could finish.
  virtual bool iterate(uint64_t iteration, const std::atomic<bool>* stop) = 0;
  // The pixel's estimate after the iterations run so far.
  virtual Color estimate(Vec2i pixel) const = 0;
  virtual std::string summary() const { return ""; }
};

// The iterative family (sppm, later vcm): the integrator owns its iteration
// body (a photon round, then a pass over every pixel) and keeps per-pixel
// statistics between iterations; a pass of the loop is one iteration. Once
// the iterations are done each pixel's estimate enters the film through its
// one entry point, once, standing for the iterations run; its variance is
// unknown. The first iterations also feed the first-hit layers, from the
// camera ray of each iteration's sample of the pixel.
class IterativeIntegrator : public Integrator {
 public:
  virtual std::unique_ptr<IterationState> begin(const Scene& scene, uint64_t seed) const = 0;
  std::unique_ptr<IntegratorRun> start(const Scene& scene, uint64_t seed) const final;
  bool splits_samples() const final { return false; }
};

}  // namespace caustica
