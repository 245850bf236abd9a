#pragma once

#include "core/shapes/shape.h"

namespace caustica {

// A shape intersected exactly by its own code, registered with Embree as
// user geometry (one primitive).
class AnalyticShape : public Shape {
 public:
  unsigned attach(RTCDevice device, RTCScene scene) const override;

  // The nearest hit with t in (t_min, t_max); fills t and the shape-defined
  // prim and uv that interaction() reads back.
  virtual bool intersect(const Ray& ray, RayHit& hit) const = 0;
};

}  // namespace caustica
