#pragma once

#include <array>
#include <vector>

#include "core/math/vec.h"

namespace caustica {

// The form factor from a differential area at x (unit normal n) to a
// triangle: the fraction of the light x's area sends in a cosine
// distribution that falls on the triangle, counting only the part of the
// triangle above x's tangent plane and ignoring occlusion. Exact, by
// Lambert's contour integral over the clipped polygon's edges; computed in
// double precision. The triangle's own facing is the caller's business.
double point_to_triangle_form_factor(Vec3 x, Vec3 n, const std::array<Vec3, 3>& triangle);

// A quadrature rule over a triangle with equal weights: the barycentric
// coordinates (b1, b2) of the centroids of the m * m triangles that split
// it at m segments per edge. Its points lie strictly inside.
std::vector<Vec2> subtriangle_centroids(int m);

}  // namespace caustica
