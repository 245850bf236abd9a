#include "integrators/radiosity/form_factor.h"

#include <cmath>
#include <numbers>

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

struct Vec3r {
  double x = 0, y = 0, z = 0;
};
Vec3r sub(Vec3r a, Vec3r b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec3r lerp(Vec3r a, Vec3r b, double t) { return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t}; }
double dot(Vec3r a, Vec3r b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3r cross(Vec3r a, Vec3r b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
Vec3r widen(Vec3 v) { return {v.x, v.y, v.z}; }

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

double point_to_triangle_form_factor(Vec3 x_in, Vec3 n_in, const std::array<Vec3, 3>& triangle) {
  const Vec3r x = widen(x_in), n = widen(n_in);
  // The triangle relative to x, clipped to the half-space above the
  // tangent plane (Sutherland-Hodgman against one plane: at most 4 corners).
  Vec3r corner[3], clipped[4];
  double height[3];
  for (int i = 0; i < 3; ++i) {
    corner[i] = sub(widen(triangle[i]), x);
    height[i] = dot(corner[i], n);
  }
  int count = 0;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (height[i] >= 0) clipped[count++] = corner[i];
    if ((height[i] >= 0) != (height[j] >= 0))
      clipped[count++] = lerp(corner[i], corner[j], height[i] / (height[i] - height[j]));
  }
  if (count < 3) return 0;
  // Each edge adds the angle it subtends times the cosine between n and
  // the normal of the plane through x and the edge.
  double sum = 0;
  for (int i = 0; i < count; ++i) {
    const Vec3r c = cross(clipped[i], clipped[(i + 1) % count]);
    const double sin_scaled = std::sqrt(dot(c, c));
    if (sin_scaled <= 0) continue;
    sum += std::atan2(sin_scaled, dot(clipped[i], clipped[(i + 1) % count])) * dot(n, c) / sin_scaled;
  }
  return std::abs(sum) / (2 * std::numbers::pi);
}

std::vector<Vec2> subtriangle_centroids(int m) {
  std::vector<Vec2> points;
  const float step = 1.0f / float(m);
  for (int i = 0; i < m; ++i)
    for (int j = 0; i + j < m; ++j) {
      points.push_back({(float(i) + 1 / 3.0f) * step, (float(j) + 1 / 3.0f) * step});
      if (i + j + 2 <= m) points.push_back({(float(i) + 2 / 3.0f) * step, (float(j) + 2 / 3.0f) * step});
    }
  return points;
}

}  // namespace caustica
