#pragma once

#include "core/bsdf/surface_bsdf.h"
#include "core/math/color.h"
#include "core/render/scatter_density.h"
#include "core/sampling/sampler.h"

namespace caustica {

class Medium;
class Scene;

// Next-event estimation where paths cross media and null surfaces: as
// sample_direct_light (core/render/direct_light.h), the shadow ray's
// visibility replaced by its transmittance.

// At a surface point reached through `arrived_in` (the medium on wo's side),
// n_bsdf BSDF samples being taken for each light sample (0: none follows,
// and the light sample takes all the weight); with `density`, the walk
// samples directions by it instead of the BSDF.
Color sample_direct_light_in_media(const Scene& scene, const SurfaceInteraction& si, const SurfaceBsdf& bsdf, Vec3 wo,
                                   const Medium* arrived_in, Sampler& sampler, float u_select, Vec2 u_light,
                                   float n_bsdf = 1, const ScatterDensity* density = nullptr);

// At a scattering event at p inside `medium`, at the path's `time`,
// weighed against sampling its phase function.
Color sample_direct_light_at_medium_point(const Scene& scene, Vec3 p, float time, const Medium& medium, Vec3 wo,
                                          Sampler& sampler, float u_select, Vec2 u_light);

}  // namespace caustica
