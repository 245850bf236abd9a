#pragma once

#include "core/geometry/bounds.h"
#include "core/math/vec.h"

namespace caustica {

// What a light tree knows of an emitter or of a group of them: where they
// are, how much they send, and the directions they send it in (every
// emitting normal or spot axis within theta_o of `axis`, each point
// emitting up to theta_e beyond its own normal).
struct LightBounds {
  Bounds3 bounds;
  float phi = 0;  // power, averaged over channels
  Vec3 axis{0, 0, 1};
  float cos_theta_o = -1;  // -1: every direction
  float cos_theta_e = 0;   // theta_e at most pi / 2

  // The bounds of both groups together.
  static LightBounds merge(const LightBounds& a, const LightBounds& b);
};

// How much light the group may send to the point p with normal n (zero for
// a point in a medium), up to one factor common to all groups: its power
// over its squared distance, times the cosines at both ends taken at the
// most favourable angle the group's bounding sphere allows. It is zero only
// where no emitter of the group can light p: where every emitting
// direction toward p lies beyond theta_o + theta_e.
float light_importance(const LightBounds& b, Vec3 p, Vec3 n);
// The same, given the centre and radius of b's bounding sphere (what a
// light tree keeps per node rather than recompute at every point).
float light_importance(const LightBounds& b, Vec3 centre, float radius, Vec3 p, Vec3 n);
// The bounding sphere's radius: half the box's diagonal.
inline float bounding_radius(const Bounds3& b) { return length(b.hi - b.lo) / 2; }

}  // namespace caustica
