#include "integrators/radiosity/element_form_factor.h"

#include "integrators/radiosity/form_factor.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

Vec3 at(const Element& e, Vec2 b) { return e.p[0] * (1 - b.x - b.y) + e.p[1] * b.x + e.p[2] * b.y; }

// Whether every corner of `e` lies on or behind the plane through p with normal n.
bool behind(const Element& e, Vec3 p, Vec3 n) {
  for (const Vec3& c : e.p)
    if (dot(c - p, n) > 0) return false;
  return true;
}

const std::vector<Vec2>& rule(int m) {
  static const std::vector<Vec2> coarse = subtriangle_centroids(2), fine = subtriangle_centroids(4);
  return m == 2 ? coarse : fine;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

float element_form_factor(const ElementSide& from, const ElementSide& to, const ElementScene* scene,
                          int visibility_rays, float offset) {
  const Element &a = *from.element, &b = *to.element;
  if (behind(b, a.p[0], from.n) || behind(a, b.p[0], to.n)) return 0;
  const bool near = length(a.centroid() - b.centroid()) < 1.5f * (a.longest_edge() + b.longest_edge());
  const std::vector<Vec2>& points = rule(near ? 4 : 2);
  double sum = 0;
  for (const Vec2 q : points) {
    const Vec3 x = at(a, q);
    if (dot(x - b.p[0], to.n) > 0) sum += point_to_triangle_form_factor(x, from.n, b.p);
  }
  const float unoccluded = float(sum / double(points.size()));
  if (unoccluded <= 0 || !scene || visibility_rays <= 0) return unoccluded;
  const std::vector<Vec2>& ends = rule(visibility_rays <= 4 ? 2 : 4);
  const int count = int(ends.size());
  int visible = 0;
  for (int k = 0; k < visibility_rays; ++k) {
    const Vec3 x = at(a, ends[k % count]) + from.n * offset;
    const Vec3 y = at(b, ends[count - 1 - k % count]) + to.n * offset;
    visible += scene->visible(x, y);
  }
  return unoccluded * float(visible) / float(visibility_rays);
}

}  // namespace caustica
