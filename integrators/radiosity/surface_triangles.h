#pragma once

#include <array>
#include <vector>

#include "core/math/vec.h"

namespace caustica {

class Scene;
class Shape;

// A flat triangle of a scene's surfaces, as radiosity meshes it.
struct SurfaceTriangle {
  std::array<Vec3, 3> p;
  std::array<Vec2, 3> uv;
  Vec3 n;  // unit normal on the shape's front (outward) side
  const Shape* shape = nullptr;
};

// Throws std::invalid_argument, naming the first shape or emitter that
// radiosity cannot render and what can, unless every surface is diffuse
// (its BSDF reflects by a diffuse lobe alone) and every emitter is an area
// emitter. Instances are refused too.
void check_radiosity_scene(const Scene& scene);

// The scene's surfaces as triangles: a triangle mesh's own, and analytic
// shapes (sphere, disk) tessellated through their area parametrisation on
// a grid fine enough for edges of about `edge` (16 to 256 cells a side).
// Triangles without area are left out.
std::vector<SurfaceTriangle> surface_triangles(const Scene& scene, float edge);

}  // namespace caustica
