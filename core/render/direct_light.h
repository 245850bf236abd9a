#pragma once

#include "core/bsdf/surface_bsdf.h"
#include "core/lights/emitter.h"
#include "core/math/color.h"

namespace caustica {

class Scene;

// Next-event estimation at a surface point: picks an emitter by power,
// samples a point on it, traces a shadow ray, and weights the result by
// multiple importance sampling against BSDF sampling (taking n_bsdf BSDF
// samples for every n_light light samples). Returns the unoccluded
// contribution f * Li * |cos| * weight / pdf, not yet multiplied by the
// path's throughput.
Color sample_direct_light(const Scene& scene, const SurfaceInteraction& si, const SurfaceBsdf& bsdf, Vec3 wo,
                          float u_select, Vec2 u_light, float n_light = 1, float n_bsdf = 1);

// The MIS weight of a BSDF-sampled direction that reached `emitter` at
// `on_light` (or the environment), from the point `from`.
float bsdf_sample_mis_weight(const Scene& scene, const Emitter& emitter, const ReferencePoint& from, Vec3 wi,
                             float bsdf_pdf, const SurfaceInteraction& on_light, float n_light = 1, float n_bsdf = 1);

}  // namespace caustica
