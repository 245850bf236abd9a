#pragma once

#include <optional>

#include "core/bsdf/surface_bsdf.h"
#include "core/lights/emitter.h"
#include "core/math/color.h"
#include "core/render/mis.h"
#include "core/render/scatter_density.h"
#include "core/spectral/wavelengths.h"

namespace caustica {

class Scene;

// A point on an emitter chosen for next-event estimation from a reference
// point: the emitter is picked by power, then the point on it.
struct ChosenLight {
  LiSample ls;
  float pdf = 0;  // selection probability times ls.pdf
  const Emitter* emitter = nullptr;

  // The MIS weight of this sample against sampling the scattering function
  // (density pdf_scatter of the same direction), n_light light samples
  // being taken for every n_bsdf scattering samples.
  float mis_weight(float pdf_scatter, float n_light = 1, float n_bsdf = 1) const {
    return ls.is_delta ? 1 : power_heuristic(n_light, pdf, n_bsdf, pdf_scatter);
  }
};

// Nothing when no emitter is chosen or it sends no light toward `ref`.
std::optional<ChosenLight> choose_light(const Scene& scene, const ReferencePoint& ref, float u_select, Vec2 u_light);

// Next-event estimation at a surface point in vacuum: a light chosen as
// above, a shadow ray, and the multiple importance sampling weight against
// BSDF sampling (taking n_bsdf BSDF samples for every n_light light
// samples). Returns the unoccluded contribution f * Li * |cos| * weight /
// pdf, not yet multiplied by the path's throughput. With `wavelengths`
// (spectral mode, the BSDF built for them) the emitter's radiance is
// lifted to them too. With `density`, the walk samples directions by it
// instead of the BSDF, and the weight is taken against it.
Color sample_direct_light(const Scene& scene, const SurfaceInteraction& si, const SurfaceBsdf& bsdf, Vec3 wo,
                          float u_select, Vec2 u_light, float n_light = 1, float n_bsdf = 1,
                          const Wavelengths* wavelengths = nullptr, const ScatterDensity* density = nullptr);

// The shadow ray from `si` toward the chosen light.
inline Ray shadow_ray(const SurfaceInteraction& si, const LiSample& ls) {
  return ls.is_infinite ? si.spawn(ls.wi) : si.spawn_to(ls.p, ls.p_error, ls.n);
}

// The MIS weight of a BSDF-sampled direction that reached `emitter` at
// `on_light` (or the environment), from the point `from`.
float bsdf_sample_mis_weight(const Scene& scene, const Emitter& emitter, const ReferencePoint& from, Vec3 wi,
                             float bsdf_pdf, const SurfaceInteraction& on_light, float n_light = 1, float n_bsdf = 1);

}  // namespace caustica
