#pragma once

#include "core/render/direct_light.h"
#include "core/scene/scene.h"
#include "core/transport/random_walk.h"

namespace caustica {

// How many next-event samples and BSDF samples the vertex before an
// emitter took, for the weight of emission met by a BSDF-sampled ray.
struct MisCounts {
  float n_light = 1, n_bsdf = 1;
};

// Emission met where a ray that arrived as `arrival` lands on `si`: calls
// add(emitter, Le, weight) if the surface emits toward wo, weight being the MIS
// weight against next-event estimation from the previous vertex (1 after
// a delta lobe or for the walk's first ray).
template <class Add>
void emission_at_surface(const Scene& scene, const SurfaceInteraction& si, Vec3 wo, const Arrival& arrival,
                         MisCounts counts, Add&& add) {
  const Emitter* emitter = si.shape->emitter();
  if (!emitter) return;
  const Color Le = emitter->L(si, wo);
  if (Le.is_black()) return;
  const float w = arrival.delta ? 1
                                : bsdf_sample_mis_weight(scene, *emitter, arrival.from, -wo, arrival.pdf, si,
                                                         counts.n_light, counts.n_bsdf);
  add(*emitter, Le, w);
}

// Emission met by a ray that leaves the scene in direction d at `time`:
// add(emitter, Le, weight) once for each environment emitter, weighed as above.
template <class Add>
void emission_from_environment(const Scene& scene, Vec3 d, float time, const Arrival& arrival, MisCounts counts,
                               Add&& add) {
  for (const Emitter* env : scene.infinite_emitters()) {
    const Color Le = env->Le_infinite(d, time);
    if (Le.is_black()) continue;
    const float w = arrival.delta ? 1
                                  : bsdf_sample_mis_weight(scene, *env, arrival.from, d, arrival.pdf,
                                                           SurfaceInteraction{}, counts.n_light, counts.n_bsdf);
    add(*env, Le, w);
  }
}

}  // namespace caustica
