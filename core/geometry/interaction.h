#pragma once

#include <algorithm>

#include "core/geometry/offset.h"
#include "core/math/frame.h"
#include "core/math/vec.h"

namespace caustica {

class Shape;

// A point on a surface as the integrators see it.
struct SurfaceInteraction {
  Vec3 p;
  Vec3 p_error;   // conservative bound on |p - exact hit point| per axis
  Vec3 ng;        // geometric normal, unit length, on the shape's outward side
  Frame shading;  // shading frame; shading.n lies on ng's side
  Vec2 uv;
  Vec3 dpdu, dpdv;  // surface tangents along the (u, v) parametrisation
  float t = kInfinity;
  const Shape* shape = nullptr;
  // The primitive Embree met within its geometry (a mesh's triangle) and the
  // scene's shape it belongs to, by its place in the scene's list.
  unsigned prim = 0, shape_index = 0;
  float time = 0;  // the time of the ray that met the surface (see Ray::time)

  Ray spawn(Vec3 d) const { return {offset_ray_origin(p, p_error, ng, d), d, kInfinity, 0, time}; }

  // A segment toward `target` that stops just short of it, for visibility.
  Ray spawn_to(Vec3 target, Vec3 target_error, Vec3 target_n) const {
    const Vec3 o = offset_ray_origin(p, p_error, ng, target - p);
    const Vec3 to = target_n == Vec3() ? target : offset_ray_origin(target, target_error, target_n, o - target);
    const Vec3 d = to - o;
    // The target is already off its surface; the margin only absorbs the
    // rounding of t itself, in proportion to the target's error bound.
    const float margin = 4 * length(target_error) / std::max(length(d), 1e-30f);
    return {o, d, std::max(0.5f, 1 - margin), 0, time};
  }
};

}  // namespace caustica
