#pragma once

#include <optional>

#include "core/lights/emitter.h"
#include "core/math/color.h"
#include "core/sampling/sampler.h"

namespace caustica {

class Scene;

// The start of a light path (for light tracing, bdpt and photons): an
// emitter chosen by power and a ray it emits.
struct LightPathStart {
  const Emitter* emitter;
  float pmf;    // of choosing the emitter
  LeSample le;  // the emitted ray and its densities
  Color beta;   // Le |cos| / (pmf pdf_pos pdf_dir): the weight the ray carries
};

// Always draws the same three numbers (selection, position, direction), so
// what follows in the path's stream does not depend on whether it started.
// None when the scene has nothing to emit or the emitter sent nothing. The
// ray leaves at `time` (see Ray::time), the time of the whole path.
std::optional<LightPathStart> start_light_path(const Scene& scene, Sampler& sampler, float time);

}  // namespace caustica
