#pragma once

#include <span>
#include <string>
#include <vector>

#include "core/geometry/ray.h"
#include "core/registry/plugin.h"
#include "core/sampling/sampler.h"

namespace caustica {

class Scene;

// An estimator of the pixel measurement. This family estimates each camera
// sample on its own (path, direct, aov); integrators that splat light-path
// contributions onto the film extend this interface when they arrive.
class Integrator : public Plugin {
 public:
  // Work that precedes the pixels (e.g. a photon pass).
  virtual void prepare(const Scene&) {}
  // Names of the values sample() writes, in order; "R", "G", "B" for radiance.
  virtual std::vector<std::string> channels() const { return {"R", "G", "B"}; }
  // Estimates the channels along one camera ray.
  virtual void sample(const Scene& scene, const Ray& ray, Sampler& sampler, std::span<float> out) const = 0;
  // Parameters as written back into the output's metadata.
  virtual std::string describe() const = 0;
};

}  // namespace caustica
