#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/math/float4.h"
#include "core/math/transform.h"
#include "core/registry/param_spec.h"
#include "core/sampling/discrete_distribution.h"
#include "core/shapes/shape.h"

namespace caustica {

class Properties;

// Mesh data in object space, as a file or a built-in shape provides it.
struct MeshData {
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;      // empty, or one per position
  std::vector<Vec2> uvs;          // empty, or one per position
  std::vector<uint32_t> indices;  // three per triangle
  bool face_normals = false;      // the file asks for flat shading
};

// Every shape made of triangles (obj, ply, rectangle, cube): stored in world
// space, intersected by Embree, sampled uniformly by area.
class TriangleMesh : public Shape {
 public:
  // Reads the parameters every mesh shape shares: to_world, flip_normals.
  TriangleMesh(MeshData mesh, const Properties& props, std::string kind);
  TriangleMesh(MeshData mesh, const Transform& to_world, bool flip_normals, std::string kind);

  unsigned attach(RTCDevice device, RTCScene scene) const override;
  SurfaceInteraction interaction(const Ray& ray, const RayHit& hit) const override;
  float area() const override { return area_; }
  Bounds3 bounds() const override;
  PositionSample sample_position(Vec2 u) const override;
  std::string kind() const override { return kind_; }
  size_t triangle_count() const { return mesh_.indices.size() / 3; }
  // The triangles in world space.
  const MeshData& data() const { return mesh_; }
  // Triangles with an area in the mesh's own space and none once stored.
  size_t collapsed_triangles() const { return collapsed_; }
  std::optional<Vec3> flat_normal() const override { return flat_normal_; }
  // Mitsuba 3's rule for meshes: with vertex normals, the squared cosine
  // between the interpolated normal and the ray; without, the distance to
  // the triangle's nearest edge in barycentric terms, 1 at its centroid
  // (3 min(b0, b1, b2)).
  float boundary_test(const SurfaceInteraction& si, Vec3 d) const override;

 private:
  // A point at barycentrics (b1, b2) of a triangle: position and its
  // error bound, the geometric normal (flipped with the mesh, facing the
  // interpolated one) and the shading normal, uv.
  struct SurfacePoint {
    Vec3 p, p_error, ng, ns;
    Vec2 uv;
  };
  // A triangle's vertex indices and positions, read once per point.
  struct Corners {
    uint32_t i0, i1, i2;
    Float4 p0, p1, p2;
  };
  Corners corners(unsigned prim) const;
  std::optional<Vec3> shared_normal() const;
  SurfacePoint point_at(const Corners& c, float b1, float b2) const;

  MeshData mesh_;
  bool flip_normals_;
  std::string kind_;
  float area_ = 0;
  size_t collapsed_ = 0;
  std::optional<DiscreteDistribution> area_distribution_;
  std::optional<Vec3> flat_normal_;
};

// The parameters of TriangleMesh, for plugins to list with their own.
std::vector<ParamSpec> mesh_shape_params();

}  // namespace caustica
