#include "core/shapes/vertex_normals.h"

#include <algorithm>
#include <cmath>

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// The angle between two edges, accurate for small and obtuse angles alike.
double angle_between(const double a[3], const double b[3]) {
  const double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  return std::atan2(std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]), a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

std::vector<Vec3> smooth_vertex_normals(const MeshData& mesh) {
  std::vector<double> sums(3 * mesh.positions.size(), 0.0);
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const uint32_t v[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
    double e[3][3];  // e[k]: from corner k to corner k + 1
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 3; ++a) e[k][a] = double(mesh.positions[v[(k + 1) % 3]][a]) - mesh.positions[v[k]][a];
    double n[3] = {e[0][1] * e[2][2] - e[0][2] * e[2][1], e[0][2] * e[2][0] - e[0][0] * e[2][2],
                   e[0][0] * e[2][1] - e[0][1] * e[2][0]};
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(length > 0)) continue;
    // cross(e0, e2) points against cross(e0, -e2), the face's orientation.
    for (double& c : n) c /= -length;
    // The angles add up to pi, so the largest (at the corner facing the
    // longest edge, at least pi / 3) is pi less the other two, as accurate
    // as they are: two atan2 calls a triangle instead of three.
    double edge2[3];
    for (int k = 0; k < 3; ++k) edge2[k] = e[k][0] * e[k][0] + e[k][1] * e[k][1] + e[k][2] * e[k][2];
    const int facing = edge2[0] >= edge2[1] ? (edge2[0] >= edge2[2] ? 0 : 2) : (edge2[1] >= edge2[2] ? 1 : 2);
    const int largest = (facing + 2) % 3;  // edge k joins corners k and k + 1; corner k + 2 faces it
    double angle[3], others = 0;
    for (int k = 0; k < 3; ++k) {
      if (k == largest) continue;
      const double in[3] = {-e[(k + 2) % 3][0], -e[(k + 2) % 3][1], -e[(k + 2) % 3][2]};
      angle[k] = angle_between(e[k], in);
      others += angle[k];
    }
    angle[largest] = M_PI - others;
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 3; ++a) sums[3 * v[k] + a] += angle[k] * n[a];
  }
  std::vector<Vec3> normals(mesh.positions.size());
  for (size_t i = 0; i < normals.size(); ++i) {
    const double* s = &sums[3 * i];
    const double length = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    if (length > 0) normals[i] = {float(s[0] / length), float(s[1] / length), float(s[2] / length)};
  }
  return normals;
}

}  // namespace caustica
