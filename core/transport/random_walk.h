#pragma once

// How every path in caustica is walked: camera paths (path, direct, sppm's
// visible points, bdpt's camera subpaths) in radiance mode, light paths
// (ptracer, bdpt's light subpaths) and photons in importance mode. The walk
// traces the ray, builds the BSDF where it lands, hands the vertex to the
// algorithm, samples the BSDF, updates the path's weight and applies the
// one Russian-roulette policy. What an algorithm does at a vertex (gather
// emission, estimate direct light, record the vertex, store a photon, stop)
// is its visitor's business; nothing else differs between algorithms.
//
// A visitor provides
//   WalkAction at_vertex(const WalkVertex&)      the ray met a surface
//   void escaped(const WalkEscape&)              the ray left the scene
//   WalkAction scattered(const BsdfSample&)      the BSDF was sampled at the last vertex
// and is called in that order along the path.

#include <cstdint>
#include <optional>

#include "core/bsdf/surface_bsdf.h"
#include "core/geometry/ray.h"
#include "core/lights/emitter.h"
#include "core/math/color.h"
#include "core/sampling/sampler.h"
#include "core/scene/scene.h"
#include "core/transport/walk_limits.h"

namespace caustica {

// How a ray left its previous vertex, which is what weighs emission it
// meets against next-event estimation from that vertex.
struct Arrival {
  bool delta = true;    // left the previous vertex through a delta lobe (true for the first ray)
  float pdf = 0;        // the solid-angle density of that BSDF sample
  ReferencePoint from;  // the previous vertex
};

// How a ray sampled by `bs` leaves `si`.
inline Arrival arrival_from(const SurfaceInteraction& si, const BsdfSample& bs) {
  return {bs.is_delta(), bs.pdf, {si.p, si.p_error, si.ng}};
}

struct WalkVertex {
  const SurfaceInteraction& si;
  const SurfaceBsdf& bsdf;
  Vec3 wo;           // toward the previous vertex
  Color beta;        // the path's weight arriving here, what the origin put in included
  int64_t segments;  // from the walk's origin to here
  bool last;         // the length limit ends the walk here
  const Arrival& arrival;
};

struct WalkEscape {
  const Ray& ray;
  Color beta;
  int64_t segments;  // counting the segment that escaped
  const Arrival& arrival;
};

enum class WalkAction { Continue, Stop };

// Walks from `ray`, which carries `beta`, until the path escapes, a visitor
// stops it, the BSDF absorbs it, roulette ends it, or it reaches
// limits.max_segments.
template <class Visitor>
void random_walk(const Scene& scene, Ray ray, Color beta, TransportMode mode, const WalkLimits& limits,
                 Sampler& sampler, Visitor& visitor) {
  if (limits.max_segments == 0) return;
  Color throughput(1);
  float eta_scale = 1;
  Arrival arrival;
  for (int64_t segments = 1;; ++segments) {
    const auto si = scene.intersect(ray);
    if (!si) {
      visitor.escaped(WalkEscape{ray, beta, segments, arrival});
      return;
    }
    const SurfaceBsdf bsdf(*si->shape->bsdf(), *si, mode);
    const Vec3 wo = -ray.d;
    const bool last = limits.max_segments >= 0 && segments >= limits.max_segments;
    if (visitor.at_vertex(WalkVertex{*si, bsdf, wo, beta, segments, last, arrival}) == WalkAction::Stop || last) return;

    const float u_lobe = sampler.next_1d();
    const auto bs = bsdf.sample(wo, u_lobe, sampler.next_2d());
    if (!bs) return;
    if (visitor.scattered(*bs) == WalkAction::Stop) return;
    const Color weight = bs->f * (abs_dot(bs->wi, si->shading.n) / bs->pdf);
    beta *= weight;
    throughput *= weight;
    if (mode == TransportMode::Radiance && bs->is_transmission()) eta_scale *= bs->eta * bs->eta;
    arrival = arrival_from(*si, *bs);
    ray = si->spawn(bs->wi);

    float q = 1;
    if (!limits.roulette.survives(segments, throughput, eta_scale, sampler, &q)) return;
    beta *= 1 / q;
    throughput *= 1 / q;
  }
}

}  // namespace caustica
