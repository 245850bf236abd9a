#pragma once

#include "core/lights/emitter.h"
#include "core/spectral/rgb_lift.h"

namespace caustica {

// Emission as a path reads it, Le being what `emitter` returned: in RGB
// mode (no wavelengths) Le itself; in spectral mode the emitter's measured
// spectrum where it has one, else Le lifted to an illuminant spectrum.
inline Color emission_for(const Emitter& emitter, Color Le, const Wavelengths* w) {
  if (!w) return Le;
  if (const MeasuredEmission* m = emitter.measured_emission()) return m->at(Le, *w);
  return lift_illuminant(Le, *w);
}

}  // namespace caustica
