#pragma once

#include <cstdint>
#include <optional>

#include "core/geometry/ray.h"
#include "core/math/vec.h"
#include "core/sampling/sampler.h"

namespace caustica {

class Scene;

// A camera ray through a pixel, placed by importance-sampling the pixel
// filter, and the weight the filter gives it.
struct CameraSample {
  Ray ray;
  float weight;
};

// Starts `sampler` on sample `index` of the pixel's camera stream and draws
// the ray from it: the filter's two numbers, then the lens's two if the
// camera has a lens, then the time in the shutter interval if anything in
// the scene moves, unless `time` fixes it (a pass whose paths share one
// instant, core/render/pass_time.h). Every algorithm that starts a path at
// the camera starts it here, so they all see the same rays.
CameraSample sample_camera_ray(const Scene& scene, Sampler& sampler, Vec2i pixel, uint64_t index, uint64_t seed,
                               std::optional<float> time = std::nullopt);

// A path's time, as a fraction of the shutter interval: drawn from the
// sampler's next number when something in the scene moves, else 0 without
// drawing, so a still scene's streams stay as they were.
float sample_shutter_time(const Scene& scene, Sampler& sampler);

}  // namespace caustica
