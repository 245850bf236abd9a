#pragma once

#include <embree3/rtcore.h>

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "core/geometry/ray.h"
#include "integrators/radiosity/surface_triangles.h"

namespace caustica {

// A triangle of the radiosity mesh, part of one surface triangle.
struct Element {
  std::array<Vec3, 3> p;
  std::array<Vec2, 3> uv;
  uint32_t surface = 0;  // index into the surface triangles
  int level = 0;         // times it was split where radiosity varies
  float area = 0;
  int32_t children = -1;  // index of the first of its four children, once split
  Vec3 centroid() const { return (p[0] + p[1] + p[2]) / 3; }
  float longest_edge() const;
};

// Each surface triangle split into n * n elements, n = ceil(longest edge /
// edge). Corners are computed from integer lattice weights, so two
// triangles split alike along a shared edge share their corners exactly.
std::vector<Element> uniform_elements(const std::vector<SurfaceTriangle>& surfaces, float edge);

// The four elements joining the edge midpoints, one level deeper: the
// children at corners 0, 1 and 2, then the middle one.
std::array<Element, 4> split(const Element& e);
// Which child of a split element holds the point at barycentrics `b`
// (of corners 1 and 2), and the point's barycentrics in that child.
std::pair<int, Vec2> child_at(Vec2 b);

// Embree over the unsplit elements, for visibility and for what a ray
// meets: split elements share their parent's plane, and leaving them out
// keeps the mesh free of the cracks T-junctions would open.
class ElementScene {
 public:
  explicit ElementScene(std::span<const Element> elements);
  ~ElementScene();
  ElementScene(const ElementScene&) = delete;
  ElementScene& operator=(const ElementScene&) = delete;

  // Whether nothing lies on the segment from `from` to `to`.
  bool visible(Vec3 from, Vec3 to) const;
  struct Hit {
    uint32_t element;
    Vec2 b;  // barycentric coordinates of corners 1 and 2
    float t;
  };
  std::optional<Hit> intersect(const Ray& ray) const;

 private:
  void attach(std::span<const Element> elements);
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
};

}  // namespace caustica
