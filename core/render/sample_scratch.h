#pragma once

#include <memory>
#include <vector>

#include "core/sampling/sampler.h"
#include "core/scene/scene.h"

namespace caustica {

// What one thread of a render loop needs: a sampler of its own and room for
// a sample's values and its first-hit layers.
struct SampleScratch {
  std::unique_ptr<Sampler> sampler;
  std::vector<float> values, aov_values;

  SampleScratch(const Scene& scene, size_t channels) : sampler(scene.sensor().sampler()->clone()), values(channels) {}
};

}  // namespace caustica
