#include "core/transport/shadow_transmittance.h"

#include <cmath>

#include "core/media/medium.h"
#include "core/scene/scene.h"
#include "core/transport/medium_crossing.h"

namespace caustica {

Color shadow_transmittance(const Scene& scene, Ray ray, const Medium* medium, Sampler& sampler) {
  // Where the segment ends, so that it can be resumed past each null surface.
  const bool infinite = std::isinf(ray.t_max);
  const Vec3 end = infinite ? Vec3() : ray.at(ray.t_max);
  Color tr(1);
  for (;;) {
    const auto si = scene.intersect(ray);
    if (si && !si->shape->is_null()) return {};
    if (medium) {
      tr *= medium->transmittance(ray, si ? si->t : ray.t_max, sampler);
      if (tr.is_black()) return {};
    }
    if (!si) return tr;
    medium = medium_after(*si, medium, ray.d);
    const Ray next = si->spawn(ray.d);
    if (infinite) {
      ray = next;
      continue;
    }
    // A null surface within its rounding margin of the end leaves nothing
    // to cross: turning toward the end would hit it again from the far side.
    if (!(dot(end - next.o, ray.d) > 0)) return tr;
    ray = {next.o, end - next.o, 1, 0, ray.time};
  }
}

Color shadow_visibility(const Scene& scene, const Ray& ray, const Medium* medium, Sampler& sampler) {
  if (scene.features().medium_walk) return shadow_transmittance(scene, ray, medium, sampler);
  return Color(scene.occluded(ray) ? 0.0f : 1.0f);
}

}  // namespace caustica
