#pragma once

#include <vector>

#include "core/shapes/triangle_mesh.h"

namespace caustica {

// Smooth vertex normals for a mesh whose file has none (as Mitsuba shades
// such meshes): each vertex takes the mean of its triangles' normals,
// weighted by the triangle's angle at that vertex, so that how a surface
// is split into triangles does not tilt its normals. Vertices of only
// degenerate triangles get a zero normal, which shading treats as absent.
std::vector<Vec3> smooth_vertex_normals(const MeshData& mesh);

}  // namespace caustica
