#pragma once

#include "core/math/vec.h"

namespace caustica {

// The density with which a vertex's walk samples its next direction, where
// it is not the BSDF's own: path guiding draws from a mixture of the BSDF
// and a learned distribution. Next-event estimation weighs its light
// sample against this density, not the BSDF's, so that the two strategies'
// weights still sum to one.
class ScatterDensity {
 public:
  virtual ~ScatterDensity() = default;
  // The density of sampling world direction wi, given the BSDF's own density of it.
  virtual float pdf(Vec3 wi, float bsdf_pdf) const = 0;
};

// The density the walk samples by: the BSDF's, or `density`'s if given.
inline float scatter_pdf(const ScatterDensity* density, Vec3 wi, float bsdf_pdf) {
  return density ? density->pdf(wi, bsdf_pdf) : bsdf_pdf;
}

}  // namespace caustica
