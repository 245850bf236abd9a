// The radiosity mesh: uniform splitting keeps the area and shares corners
// exactly along a shared edge (so corner values can meet by position), and
// a point found in a split element's child is the same point.

#include "integrators/radiosity/element_mesh.h"

#include <gtest/gtest.h>

#include <random>
#include <set>
#include <tuple>

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

Vec3 at(const Element& e, Vec2 b) { return e.p[0] * (1 - b.x - b.y) + e.p[1] * b.x + e.p[2] * b.y; }

TEST(ElementMesh, UniformSplitKeepsAreaAndSharesEdgeCorners) {
  // Two triangles sharing the edge (b, c), listed in opposite orders.
  const Vec3 a{0.1f, 0.2f, 0.3f}, b{1.7f, 0.1f, 0.2f}, c{0.3f, 1.9f, 0.7f}, d{1.9f, 1.3f, -0.4f};
  const std::vector<SurfaceTriangle> surfaces{{{a, b, c}, {}, {}, nullptr}, {{d, c, b}, {}, {}, nullptr}};
  const auto elements = uniform_elements(surfaces, 0.3f);
  double area[2] = {0, 0};
  std::set<std::tuple<float, float, float>> corners[2];
  for (const Element& e : elements) {
    area[e.surface] += e.area;
    EXPECT_LE(e.longest_edge(), 0.3f * 1.0001f);
    for (const Vec3& p : e.p) corners[e.surface].insert({p.x, p.y, p.z});
  }
  EXPECT_NEAR(area[0], 0.5 * length(cross(b - a, c - a)), 1e-5);
  EXPECT_NEAR(area[1], 0.5 * length(cross(c - d, b - d)), 1e-5);
  // Every corner of the first on the shared edge is a corner of the second.
  int shared = 0;
  for (const auto& [x, y, z] : corners[0]) {
    const Vec3 p{x, y, z};
    const Vec3 along = c - b;
    const float s = dot(p - b, along) / dot(along, along);
    if (length(p - (b + along * s)) > 1e-5f) continue;
    ++shared;
    EXPECT_TRUE(corners[1].count({x, y, z})) << x << " " << y << " " << z;
  }
  EXPECT_GE(shared, 7);
}

TEST(ElementMesh, ChildAtFindsTheSamePoint) {
  const Element parent =
      uniform_elements({{{Vec3{0, 0, 0}, Vec3{2, 0.1f, 0}, Vec3{0.3f, 1.5f, 0.2f}}, {}, {}, nullptr}}, 10)[0];
  const auto children = split(parent);
  float children_area = 0;
  for (const Element& child : children) children_area += child.area;
  EXPECT_NEAR(children_area, parent.area, 1e-5f);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0, 1);
  int found[4] = {0, 0, 0, 0};
  for (int i = 0; i < 2000; ++i) {
    Vec2 b{u(rng), u(rng)};
    if (b.x + b.y > 1) b = {1 - b.x, 1 - b.y};
    const auto [child, local] = child_at(b);
    ++found[child];
    EXPECT_GE(local.x, -1e-5f);
    EXPECT_GE(local.y, -1e-5f);
    EXPECT_LE(local.x + local.y, 1 + 1e-5f);
    const Vec3 expected = at(parent, b), got = at(children[size_t(child)], local);
    EXPECT_LT(length(expected - got), 1e-5f) << "child " << child;
  }
  for (int c = 0; c < 4; ++c) EXPECT_GT(found[c], 300) << c;
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
