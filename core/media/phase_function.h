#pragma once

#include <optional>

#include "core/math/vec.h"
#include "core/registry/plugin.h"

namespace caustica {

// A direction sampled by a phase function. Phase functions here are sampled
// exactly, so the sample's weight p / pdf is 1 and only the density is kept.
struct PhaseSample {
  Vec3 wi;
  float pdf = 0;
};

// How a medium scatters light, per unit solid angle: p(wo, wi) integrates
// to 1 over wi. wo points toward where the light goes (the previous vertex
// of a camera path), wi toward where it comes from, both away from the
// scattering point; a forward-scattering medium (g > 0) favours wi = -wo.
// Phase functions are reciprocal: p(wo, wi) = p(wi, wo).
class PhaseFunction : public Plugin {
 public:
  // The density, which is also the pdf of sample().
  virtual float eval(Vec3 wo, Vec3 wi) const = 0;
  virtual std::optional<PhaseSample> sample(Vec3 wo, Vec2 u) const = 0;
  // The mean cosine between the light's direction before and after scattering.
  virtual float mean_cosine() const = 0;
};

}  // namespace caustica
