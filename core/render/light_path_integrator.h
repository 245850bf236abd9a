#pragma once

#include <cstdint>
#include <memory>
#include <span>

#include "core/render/integrator.h"
#include "core/sampling/sampler.h"

namespace caustica {

// The light-path family (ptracer, bdpt): a sample belongs to a pixel and an
// index but may light any pixel, through splats where its light paths join
// the camera. The integrator starts its own sample stream from the pixel
// and index it receives (bdpt its pixel's camera stream, in which its light
// subpath follows the camera subpath; ptracer its pixel's light-path
// stream). The loop renders the tiles in
// chunks; each tile collects its splats in its own list, and the lists
// enter the film in tile order, in parallel over bands of rows, so every
// pixel receives its splats in the same order for any thread count.
class LightPathIntegrator : public Integrator {
 public:
  // One sample: writes `out` for its own pixel (zeros if it writes none)
  // and returns the film weight of `out`; adds splats anywhere.
  virtual float sample(const Scene& scene, SampleId id, uint64_t seed, Sampler& sampler, std::span<float> out,
                       SplatList& splats) const = 0;
  std::unique_ptr<IntegratorRun> start(const Scene& scene, uint64_t seed) const final;
};

}  // namespace caustica
