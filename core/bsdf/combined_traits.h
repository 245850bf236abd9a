#pragma once

#include <cstdint>

#include "core/bsdf/bsdf.h"

namespace caustica {

// What a BSDF made of two others (twosided, blendbsdf) says of itself,
// worked out once as it is built: asked of both parts at every query, a
// chain of such BSDFs whose parts are the link before asks 2^n times.
struct CombinedTraits {
  CombinedTraits(const Bsdf& a, const Bsdf& b)
      : lobes(a.lobes() | b.lobes()),
        reads_tangents(a.reads_tangents() || b.reads_tangents()),
        renders_spectral(a.renders_spectral() && b.renders_spectral()),
        disperses(a.disperses() || b.disperses()) {}

  uint32_t lobes;
  bool reads_tangents, renders_spectral, disperses;
};

}  // namespace caustica
