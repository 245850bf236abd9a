#pragma once

#include "core/lights/spectral_emission.h"
#include "core/render/direct_light.h"
#include "core/render/path_settings.h"
#include "core/scene/scene.h"
#include "core/transport/direct_light_in_media.h"
#include "core/transport/emission.h"
#include "core/transport/random_walk.h"
#include "integrators/path/path_tracing.h"

namespace caustica {

// Gathers emission met and next-event estimates along a camera walk; with
// kMedia, through media and null surfaces too.
template <bool kMedia>
class PathRadiance {
 public:
  PathRadiance(const Scene& scene, Sampler& sampler, const PathSettings& settings, const CausticEstimator* caustics,
               const Wavelengths* wavelengths)
      : scene_(scene), sampler_(sampler), settings_(settings), caustics_(caustics), wavelengths_(wavelengths) {}

  WalkAction at_vertex(const WalkVertex& v) {
    gather_emission(v);
    return estimate_direct_light(v);
  }

  // at_vertex's two halves: the emission the walk meets at the vertex, and
  // next-event estimation from it.
  void gather_emission(const WalkVertex& v) {
    if (shows_emission(v.segments))
      emission_at_surface(scene_, v.si, v.wo, v.arrival, {}, [&](const Emitter& e, Color Le, float w) {
        L += v.beta * emission_for(e, Le, wavelengths_) * w;
      });
  }
  // Without `sample_lights` (where a guided walk has learnt that light
  // samples reach no light) it takes none, but draws their numbers still,
  // so that later dimensions keep their meaning.
  WalkAction estimate_direct_light(const WalkVertex& v, bool sample_lights = true) {
    if (v.last) return WalkAction::Stop;
    const float u_select = sampler_.next_1d();
    const Vec2 u_light = sampler_.next_2d();
    if (!sample_lights) return WalkAction::Continue;
    const bool non_delta = v.bsdf.lobes() & ~kDelta;
    if (non_delta) {
      if constexpr (kMedia)
        L += v.beta * sample_direct_light_in_media(scene_, v.si, v.bsdf, v.wo, v.medium, sampler_, u_select, u_light, 1,
                                                   density_);
      else
        L += v.beta * sample_direct_light(scene_, v.si, v.bsdf, v.wo, u_select, u_light, 1, 1, wavelengths_, density_);
    }
    if (non_delta && caustics_) L += v.beta * caustics_->estimate(v.si, v.bsdf, v.wo, v.segments);
    return WalkAction::Continue;
  }

  void escaped(const WalkEscape& e) {
    if (shows_emission(e.segments))
      emission_from_environment(scene_, e.ray.d, e.ray.time, e.arrival, {},
                                [&](const Emitter& emitter, Color Le, float w) {
                                  L += e.beta * emission_for(emitter, Le, wavelengths_) * w;
                                });
  }

  WalkAction at_medium_vertex(const MediumVertex& v) requires kMedia {
    if (v.last) return WalkAction::Stop;
    const float u_select = sampler_.next_1d();
    const Vec2 u_light = sampler_.next_2d();
    if (v.medium.sample_emitters())
      L += v.beta *
           sample_direct_light_at_medium_point(scene_, v.p, v.time, v.medium, v.wo, sampler_, u_select, u_light);
    return WalkAction::Continue;
  }

  // Caustic photons stop where they scatter in a medium, so what this path
  // finds past a scattering event is its own to count.
  WalkAction scattered_in_medium(const PhaseSample&) requires kMedia {
    gathered_ = false;
    delta_bounces_since_ = 0;
    return WalkAction::Continue;
  }

  WalkAction scattered(const BsdfSample& bs) {
    if (caustics_ && !bs.is_delta()) {
      gathered_ = true;
      delta_bounces_since_ = 0;
    } else if (gathered_) {
      ++delta_bounces_since_;
    }
    return WalkAction::Continue;
  }

  Color L;

 protected:
  // Where the walk samples directions by other than the BSDF, its density
  // at the current vertex, for next-event estimation's weight.
  const ScatterDensity* density_ = nullptr;
  Sampler& sampler() { return sampler_; }

 private:
  // The caustic estimator has the light this path finds next when the path
  // left its last non-delta vertex (where it gathered) by a non-delta
  // bounce, and only delta bounces followed.
  bool shows_emission(int64_t segments) const {
    return (segments > 1 || !settings_.hide_emitters) && !(gathered_ && delta_bounces_since_ > 0);
  }

  const Scene& scene_;
  Sampler& sampler_;
  const PathSettings& settings_;
  const CausticEstimator* caustics_;
  const Wavelengths* wavelengths_;
  bool gathered_ = false;
  int delta_bounces_since_ = 0;
};

}  // namespace caustica
