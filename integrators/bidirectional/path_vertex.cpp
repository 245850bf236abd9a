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

ScatteringBothWays scattering_both_ways(const PathVertex& v, Vec3 w_prev, Vec3 w_next) {
  if (v.in_medium()) {
    const PhaseFunction& phase = v.medium->phase();
    const float p = phase.eval(w_prev, w_next);
    return {Color(p), p, phase.eval(w_next, w_prev)};
  }
  const SurfaceBsdf::EvalPdfs e = v.bsdf->eval_and_pdfs(w_prev, w_next);
  return {e.f * abs_dot(w_next, v.si.shading.n), e.pdf.forward, e.pdf.backward};
}

const Medium* medium_toward(const PathVertex& v, Vec3 w) {
  return v.is_surface() ? medium_after(v.si, v.medium, w) : v.medium;
}

}  // namespace caustica
