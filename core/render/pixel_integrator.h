#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>

#include "core/geometry/ray.h"
#include "core/math/color.h"
#include "core/render/integrator.h"
#include "core/sampling/sampler.h"

namespace caustica {

// The state of one render of a per-pixel estimator.
class PixelEstimator {
 public:
  virtual ~PixelEstimator() = default;
  // Before the samples of `range` (core/render/pass_schedule.h), e.g. to
  // trace its pass's round of photons; false if `stop` (may be null) ended
  // that before the samples could run.
  virtual bool begin_pass(const PassRange& /*range*/, const std::atomic<bool>* /*stop*/) { return true; }
  virtual uint32_t max_pass_samples() const { return 16; }
  // The time every camera ray of the pass begun last is traced at, when
  // the pass's paths must share one (core/render/pass_time.h); else each
  // ray draws its own.
  virtual std::optional<float> pass_time() const { return std::nullopt; }
  // Estimates the channels along one camera ray through `pixel`; every
  // number it draws comes from `sampler`, which is on the pixel's camera
  // stream. The samples of one pixel in a pass come from one thread, in
  // index order.
  virtual void sample(Vec2i pixel, const Ray& ray, Sampler& sampler, std::span<float> out) const = 0;
  virtual std::string summary() const { return ""; }
};

// The per-pixel family (path, direct, aov, photon): each sample of a pixel
// is a camera ray through it, placed by the pixel filter, and the estimate
// along it enters that pixel. The loop runs tiles in parallel, the samples
// of a pixel in index order.
class PixelIntegrator : public Integrator {
 public:
  virtual std::unique_ptr<PixelEstimator> estimator(const Scene& scene, uint64_t seed) const = 0;
  std::unique_ptr<IntegratorRun> start(const Scene& scene, uint64_t seed) const final;
};

// A per-pixel estimator of RGB radiance that keeps no state of its own.
class RadianceIntegrator : public PixelIntegrator {
 public:
  virtual Color Li(const Scene& scene, Ray ray, Sampler& sampler) const = 0;
  std::unique_ptr<PixelEstimator> estimator(const Scene& scene, uint64_t seed) const override;
};

}  // namespace caustica
