#pragma once

#include "core/math/color.h"
#include "core/render/integrator.h"

namespace caustica {

// An integrator whose estimate is the RGB radiance arriving along the ray.
class RadianceIntegrator : public Integrator {
 public:
  virtual Color Li(const Scene& scene, Ray ray, Sampler& sampler) const = 0;

  void sample(const Scene& scene, const Ray& ray, Sampler& sampler, std::span<float> out, SplatList&) const final {
    const Color L = Li(scene, ray, sampler);
    out[0] = L.r;
    out[1] = L.g;
    out[2] = L.b;
  }
};

}  // namespace caustica
