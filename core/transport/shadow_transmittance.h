#pragma once

#include "core/geometry/ray.h"
#include "core/math/color.h"
#include "core/sampling/sampler.h"

namespace caustica {

class Medium;
class Scene;

// The fraction of light that passes along a shadow ray (from its origin to
// ray.t_max) which starts in `medium`: zero where a surface that scatters
// blocks it; through null surfaces it continues, in the medium they lead
// into, and every medium crossed multiplies its transmittance in.
Color shadow_transmittance(const Scene& scene, Ray ray, const Medium* medium, Sampler& sampler);

// The same fraction for a scene of any kind: where the scene's walks never
// meet a medium, one occlusion query decides between 0 and 1.
Color shadow_visibility(const Scene& scene, const Ray& ray, const Medium* medium, Sampler& sampler);

}  // namespace caustica
