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
// and is called in that order along the path. A visitor that samples
// directions by something other than the BSDF (path guiding) provides
//   std::optional<BsdfSample> sample_scattering(const WalkVertex&, float u_lobe, Vec2 u)
// returning the direction, the BSDF's value there and the density it was
// drawn with, from the numbers the BSDF would have been sampled with, and
// may provide
//   Color roulette_weight(const WalkVertex&, const BsdfSample&)
// the factor by which the sample changes the throughput Russian roulette
// judges (else the sample's weight f |cos| / pdf), and
//   bool sampled_lights() const
// whether it estimated direct light at the last vertex (else it always
// does): where it did not, the emission the sampled direction meets is
// that vertex's only estimate of it and weighs in full, as after a delta
// lobe. Visitors that handle media
// also provide
//   WalkAction at_medium_vertex(const MediumVertex&)   the ray scattered in a medium
//   WalkAction scattered_in_medium(const PhaseSample&) the phase function was sampled there
// and their walks, in scenes with media or null surfaces, sample free
// flights along every segment and step through null surfaces (which are
// no vertex and count no segment). Scenes with neither walk without a
// medium branch.

#include <concepts>
#include <cstdint>
#include <optional>

#include "core/bsdf/surface_bsdf.h"
#include "core/geometry/ray.h"
#include "core/lights/emitter.h"
#include "core/math/color.h"
#include "core/media/medium.h"
#include "core/sampling/sampler.h"
#include "core/scene/scene.h"
#include "core/transport/medium_crossing.h"
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
  return {bs.is_delta(), bs.pdf, {si.p, si.p_error, si.ng, si.time}};
}

struct WalkVertex {
  const SurfaceInteraction& si;
  const SurfaceBsdf& bsdf;
  Vec3 wo;           // toward the previous vertex
  Color beta;        // the path's weight arriving here, what the origin put in included
  int64_t segments;  // from the walk's origin to here
  bool last;         // the length limit ends the walk here
  const Arrival& arrival;
  const Medium* medium;  // the medium the ray arrived through (null: vacuum)
};

// A scattering event inside a medium.
struct MediumVertex {
  Vec3 p;
  Vec3 wo;  // toward the previous vertex, unit length
  const Medium& medium;
  Color beta;  // the path's weight arriving here, sigma_s included
  int64_t segments;
  bool last;
  const Arrival& arrival;
  float time;  // the path's (see Ray::time)
};

struct WalkEscape {
  const Ray& ray;
  Color beta;
  int64_t segments;  // counting the segment that escaped
  const Arrival& arrival;
};

enum class WalkAction { Continue, Stop };

template <class Visitor>
concept MediumVisitor = requires(Visitor& v, const MediumVertex& mv, const PhaseSample& ps) {
  { v.at_medium_vertex(mv) } -> std::same_as<WalkAction>;
  { v.scattered_in_medium(ps) } -> std::same_as<WalkAction>;
};

template <class Visitor>
concept ScatteringSampler = requires(Visitor& v, const WalkVertex& wv, float u_lobe, Vec2 u) {
  { v.sample_scattering(wv, u_lobe, u) } -> std::same_as<std::optional<BsdfSample>>;
};

template <class Visitor>
concept RouletteWeigher = requires(Visitor& v, const WalkVertex& wv, const BsdfSample& bs) {
  { v.roulette_weight(wv, bs) } -> std::same_as<Color>;
};

template <class Visitor>
concept LightSampleSkipper = requires(const Visitor& v) {
  { v.sampled_lights() } -> std::same_as<bool>;
};

template <bool kMedia, class Visitor>
void walk_segments(const Scene& scene, Ray ray, Color beta, TransportMode mode, const WalkLimits& limits,
                   Sampler& sampler, Visitor& visitor, const Medium* medium, Wavelengths* wavelengths) {
  if (limits.max_segments == 0) return;
  Color throughput(1);
  float eta_scale = 1;
  Arrival arrival;
  for (int64_t segments = 1;; ++segments) {
    auto si = scene.intersect(ray);
    const bool last = limits.max_segments >= 0 && segments >= limits.max_segments;
    if constexpr (kMedia) {
      std::optional<float> t_scatter;  // the ray parameter of a scattering event in the medium
      for (;;) {
        if (medium) {
          const FreeFlight flight = medium->sample_free_flight(ray, si ? si->t : kInfinity, beta, sampler);
          beta *= flight.weight;
          throughput *= flight.weight;
          if (flight.scattered) {
            t_scatter = flight.t;
            break;
          }
        }
        if (!si || !si->shape->is_null()) break;
        medium = medium_after(*si, medium, ray.d);
        ray = si->spawn(ray.d);
        si = scene.intersect(ray);
      }
      if (beta.is_black()) return;
      if (t_scatter) {
        const Vec3 p = ray.at(*t_scatter);
        const Vec3 wo = -normalize(ray.d);
        if (visitor.at_medium_vertex(MediumVertex{p, wo, *medium, beta, segments, last, arrival, ray.time}) ==
                WalkAction::Stop ||
            last)
          return;
        const auto ps = medium->phase().sample(wo, sampler.next_2d());
        if (!ps || visitor.scattered_in_medium(*ps) == WalkAction::Stop) return;
        // A phase function is sampled exactly: the weight p / pdf is 1.
        arrival = {!medium->sample_emitters(), ps->pdf, {p, {}, {}, ray.time}};
        ray = {p, ps->wi, kInfinity, 0, ray.time};
        float q = 1;
        if (!limits.roulette.survives(segments, throughput, eta_scale, sampler, &q)) return;
        beta *= 1 / q;
        throughput *= 1 / q;
        continue;
      }
    }

    if (!si) {
      visitor.escaped(WalkEscape{ray, beta, segments, arrival});
      return;
    }
    const SurfaceBsdf bsdf(*si->shape->bsdf(), *si, mode, wavelengths);
    if (wavelengths && bsdf.disperses() && !secondaries_terminated(*wavelengths)) {
      terminate_secondaries(*wavelengths);
      beta = hero_only(beta);
      throughput = hero_only(throughput);
    }
    const Vec3 wo = -ray.d;
    const WalkVertex vertex{*si, bsdf, wo, beta, segments, last, arrival, medium};
    if (visitor.at_vertex(vertex) == WalkAction::Stop || last) return;

    const float u_lobe = sampler.next_1d();
    const Vec2 u = sampler.next_2d();
    std::optional<BsdfSample> bs;
    if constexpr (ScatteringSampler<Visitor>)
      bs = visitor.sample_scattering(vertex, u_lobe, u);
    else
      bs = bsdf.sample(wo, u_lobe, u);
    if (!bs) return;
    if (visitor.scattered(*bs) == WalkAction::Stop) return;
    const Color weight = bs->f * (abs_dot(bs->wi, si->shading.n) / bs->pdf);
    beta *= weight;
    if constexpr (RouletteWeigher<Visitor>)
      throughput *= visitor.roulette_weight(vertex, *bs);
    else
      throughput *= weight;
    if (mode == TransportMode::Radiance && bs->is_transmission()) eta_scale *= bs->eta * bs->eta;
    arrival = arrival_from(*si, *bs);
    if constexpr (LightSampleSkipper<Visitor>)
      if (!visitor.sampled_lights()) arrival.delta = true;
    ray = si->spawn(bs->wi);
    if constexpr (kMedia) medium = medium_after(*si, medium, bs->wi);

    float q = 1;
    if (!limits.roulette.survives(segments, throughput, eta_scale, sampler, &q)) return;
    beta *= 1 / q;
    throughput *= 1 / q;
  }
}

// Walks from `ray`, which carries `beta` and starts in `medium`, until the
// path escapes, a visitor stops it, the BSDF absorbs it, roulette ends it,
// or it reaches limits.max_segments. With `wavelengths` (spectral mode) the
// BSDFs return values at them, and beta holds the path's values there; a
// dispersive surface terminates the secondary wavelengths (in the shared
// `wavelengths`, so that whatever else the sample adds follows the hero).
template <class Visitor>
void random_walk(const Scene& scene, Ray ray, Color beta, TransportMode mode, const WalkLimits& limits,
                 Sampler& sampler, Visitor& visitor, const Medium* medium = nullptr,
                 Wavelengths* wavelengths = nullptr) {
  if constexpr (MediumVisitor<Visitor>) {
    if (scene.features().medium_walk) {
      walk_segments<true>(scene, ray, beta, mode, limits, sampler, visitor, medium, wavelengths);
      return;
    }
  }
  walk_segments<false>(scene, ray, beta, mode, limits, sampler, visitor, nullptr, wavelengths);
}

}  // namespace caustica
