#pragma once

#include <memory>

#include "core/geometry/ray.h"
#include "core/math/color.h"
#include "core/media/phase_function.h"
#include "core/registry/plugin.h"
#include "core/sampling/sampler.h"

namespace caustica {

// Where free-flight sampling along a segment of a ray ended.
struct FreeFlight {
  bool scattered = false;  // a scattering event before the segment's end
  float t = 0;             // its ray parameter, when scattered
  // What the path's weight is multiplied by: transmittance times sigma_s
  // over the density of the event sampled (a scattering at t, or passing
  // the whole segment), averaged over the channels that could have drawn
  // it (one-sample MIS between channels): unbiased for every channel.
  Color weight{1};
};

// A participating medium: light is absorbed (sigma_a) and scattered
// (sigma_s, by the phase function) along every segment through it, so
// radiance falls by the transmittance exp(-integral of sigma_t) and gains
// what is scattered in. Coefficients are per unit of scene length and per
// colour channel.
class Medium : public Plugin {
 public:
  // Samples where a ray (not necessarily of unit direction) travelling
  // from its origin first interacts before ray parameter t_max, for a path
  // whose weight is `beta`. Where channels differ, they share the sampling
  // in proportion to beta, which keeps the sum of beta's channels from
  // growing at any event (a uniform share lets one channel's weight grow
  // without bound over many scatterings).
  virtual FreeFlight sample_free_flight(const Ray& ray, float t_max, Color beta, Sampler& sampler) const = 0;
  // The transmittance from the ray's origin to ray parameter t_max (an
  // unbiased estimate where it is not known in closed form).
  virtual Color transmittance(const Ray& ray, float t_max, Sampler& sampler) const = 0;
  // Constant coefficients everywhere.
  virtual bool is_homogeneous() const = 0;
  // sigma_t differs between channels.
  virtual bool is_chromatic() const = 0;

  const PhaseFunction& phase() const { return *phase_; }
  // Whether direct light is estimated at scattering events in the medium
  // (Mitsuba's sample_emitters; without it only phase sampling finds lights).
  bool sample_emitters() const { return sample_emitters_; }

 protected:
  // What every medium takes: the nested <phase> (isotropic when there is
  // none) and sample_emitters.
  void read_common(const class Properties& props);

 private:
  std::shared_ptr<PhaseFunction> phase_;
  bool sample_emitters_ = true;
};

}  // namespace caustica
