#include "integrators/bidirectional/path_vertex.h"

#include "core/media/medium.h"
#include "core/transport/medium_crossing.h"

namespace caustica {

bool joinable(const PathVertex& v) { return v.in_medium() || (v.bsdf->lobes() & ~kDelta); }

bool specular(const PathVertex& v) { return v.is_surface() && v.delta && !joinable(v) && !v.emitter; }

Color scattering(const PathVertex& v, Vec3 w_prev, Vec3 w_next) {
  if (v.in_medium()) return Color(v.medium->phase().eval(w_prev, w_next));
  return v.bsdf->eval(w_prev, w_next) * abs_dot(w_next, v.si.shading.n);
}

const Medium* medium_toward(const PathVertex& v, Vec3 w) {
  return v.is_surface() ? medium_after(v.si, v.medium, w) : v.medium;
}

}  // namespace caustica
