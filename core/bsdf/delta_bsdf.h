#pragma once

#include "core/bsdf/bsdf.h"

namespace caustica {

// A BSDF of delta lobes only (smooth mirrors and glass): it scatters into
// discrete directions, so no pair of directions has a value or a density,
// and only sample() carries light.
class DeltaBsdf : public Bsdf {
 public:
  Color eval(const BsdfContext&, Vec3, Vec3) const final { return {}; }
  float pdf(const BsdfContext&, Vec3, Vec3) const final { return 0; }
  bool reads_tangents() const override { return false; }
};

}  // namespace caustica
