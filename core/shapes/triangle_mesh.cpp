#include "core/shapes/triangle_mesh.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/math/float4.h"
#include "core/registry/properties.h"
#include "core/sampling/warp.h"

namespace caustica {

std::vector<ParamSpec> mesh_shape_params() {
  return {{"to_world", ParamType::Transform, "", "object-to-world transform"},
          {"flip_normals", ParamType::Boolean, "false", "turn the surface inside out (emission side too)"}};
}

TriangleMesh::TriangleMesh(MeshData mesh, const Properties& props, std::string kind)
    : TriangleMesh(std::move(mesh), props.get_transform("to_world"), props.get_bool("flip_normals"), std::move(kind)) {
  if (collapsed_ > 0)
    props.warn("to_world", std::to_string(collapsed_) +
                               " triangles collapse to lines or points once stored in float relative to the camera: "
                               "they are finer than float's spacing at their distance");
}

TriangleMesh::TriangleMesh(MeshData mesh, const Transform& to_world, bool flip_normals, std::string kind)
    : mesh_(std::move(mesh)), flip_normals_(flip_normals), kind_(std::move(kind)) {
  for (uint32_t index : mesh_.indices)
    if (index >= mesh_.positions.size())
      throw std::invalid_argument(kind_ + " mesh: vertex index " + std::to_string(index) + " is out of range (" +
                                  std::to_string(mesh_.positions.size()) + " vertices)");
  if (mesh_.indices.size() % 3 != 0) throw std::invalid_argument(kind_ + " mesh: indices do not form triangles");
  // In double: a squared area is a side's fourth power, which leaves
  // float's range for sides beyond about 1e9 (the scene is then refused
  // for its size, not for an area).
  const auto area2 = [&](size_t i) {
    const Vec3 p0 = mesh_.positions[mesh_.indices[i]], p1 = mesh_.positions[mesh_.indices[i + 1]],
               p2 = mesh_.positions[mesh_.indices[i + 2]];
    const double ax = double(p1.x) - p0.x, ay = double(p1.y) - p0.y, az = double(p1.z) - p0.z;
    const double bx = double(p2.x) - p0.x, by = double(p2.y) - p0.y, bz = double(p2.z) - p0.z;
    const double cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
    return cx * cx + cy * cy + cz * cz;
  };
  std::vector<bool> had_area(triangle_count());
  for (size_t i = 0; i < mesh_.indices.size(); i += 3) had_area[i / 3] = area2(i) > 0;
  for (Vec3& p : mesh_.positions) p = to_world.point(p);
  for (Vec3& n : mesh_.normals) n = normalize(to_world.normal(n));
  // Embree reads each vertex with a 16-byte load; the spare capacity keeps
  // the last one's read inside the allocation.
  mesh_.positions.reserve(mesh_.positions.size() + 1);
  std::vector<float> areas;
  areas.reserve(triangle_count());
  for (size_t i = 0; i < mesh_.indices.size(); i += 3) {
    const double stored2 = area2(i);
    collapsed_ += had_area[i / 3] && !(stored2 > 0);
    areas.push_back(float(0.5 * std::sqrt(stored2)));
    area_ += areas.back();
  }
  // A mesh of only degenerate triangles can still be hit-tested, but not sampled.
  if (area_ > 0) area_distribution_.emplace(areas);
  flat_normal_ = shared_normal();
}

// The normal interaction() gives every triangle, where all agree to within
// 1.5e-3 radians and no vertex normal would turn it over.
std::optional<Vec3> TriangleMesh::shared_normal() const {
  std::optional<Vec3> shared;
  for (size_t i = 0; i < mesh_.indices.size(); i += 3) {
    const Vec3 p0 = mesh_.positions[mesh_.indices[i]], p1 = mesh_.positions[mesh_.indices[i + 1]],
               p2 = mesh_.positions[mesh_.indices[i + 2]];
    const Vec3 c = cross(p1 - p0, p2 - p0);
    if (!(dot(c, c) > 0)) continue;
    const Vec3 n = normalize(flip_normals_ ? -c : c);
    if (!shared) shared = n;
    if (!(dot(n, *shared) > 1 - 1e-6f)) return std::nullopt;
  }
  if (!shared) return std::nullopt;
  for (const Vec3& vn : mesh_.normals)
    if (!(dot(flip_normals_ ? -vn : vn, *shared) > 0)) return std::nullopt;
  return shared;
}

unsigned TriangleMesh::attach(RTCDevice device, RTCScene scene) const {
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, mesh_.positions.data(), 0,
                             sizeof(Vec3), mesh_.positions.size());
  rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, mesh_.indices.data(), 0,
                             3 * sizeof(uint32_t), triangle_count());
  rtcCommitGeometry(geom);
  const unsigned id = rtcAttachGeometry(scene, geom);
  rtcReleaseGeometry(geom);
  return id;
}

Bounds3 TriangleMesh::bounds() const {
  Bounds3 b;
  for (const Vec3& p : mesh_.positions) b.expand(p);
  return b;
}

TriangleMesh::Corners TriangleMesh::corners(unsigned prim) const {
  const uint32_t* i = &mesh_.indices[3 * size_t(prim)];
  return {i[0],
          i[1],
          i[2],
          to_float4(mesh_.positions[i[0]]),
          to_float4(mesh_.positions[i[1]]),
          to_float4(mesh_.positions[i[2]])};
}

TriangleMesh::SurfacePoint TriangleMesh::point_at(const Corners& c, float b1, float b2) const {
  const float b0 = 1 - b1 - b2;
  const Float4 w0 = c.p0 * b0, w1 = c.p1 * b1, w2 = c.p2 * b2;

  SurfacePoint sp;
  // The point is interpolated from the vertices rather than taken as o + t d:
  // its error then depends only on the vertices, not on the ray's length.
  // The bound has an isotropic part too: Embree intersects relative to the
  // vertices, so a ray leaving a point exactly on an axis-aligned plane
  // (where the interpolation is exact) still needs to clear Embree's own
  // rounding, which scales with the vertex coordinates.
  sp.p = to_vec3(w0 + w1 + w2);
  const float magnitude = max_component(max(max(abs(c.p0), abs(c.p1)), abs(c.p2)));
  sp.p_error = to_vec3(max((abs(w0) + abs(w1) + abs(w2)) * gamma(7), Float4{} + magnitude * gamma(7)));
  Float4 ng = normalize(cross(c.p1 - c.p0, c.p2 - c.p0));
  if (flip_normals_) ng = -ng;
  sp.ng = to_vec3(ng);
  sp.ns = sp.ng;
  if (!mesh_.normals.empty()) {
    const Float4 interpolated =
        to_float4(mesh_.normals[c.i0]) * b0 + to_float4(mesh_.normals[c.i1]) * b1 + to_float4(mesh_.normals[c.i2]) * b2;
    if (dot(interpolated, interpolated) > 0) {
      Float4 ns = normalize(interpolated);
      if (flip_normals_) ns = -ns;
      sp.ns = to_vec3(ns);
      if (dot(ng, ns) < 0) sp.ng = -sp.ng;
    }
  }
  sp.uv = mesh_.uvs.empty() ? Vec2(b1, b2) : mesh_.uvs[c.i0] * b0 + mesh_.uvs[c.i1] * b1 + mesh_.uvs[c.i2] * b2;
  return sp;
}

SurfaceInteraction TriangleMesh::interaction(const Ray&, const RayHit& hit) const {
  const Corners c = corners(hit.prim);
  const SurfacePoint sp = point_at(c, hit.uv.x, hit.uv.y);
  SurfaceInteraction si;
  si.p = sp.p;
  si.p_error = sp.p_error;
  si.t = hit.t;
  si.shape = this;
  si.ng = sp.ng;
  si.uv = sp.uv;
  // Tangents from the uv parametrisation (barycentric when there are no uvs).
  const Vec2 uv0 = mesh_.uvs.empty() ? Vec2(0, 0) : mesh_.uvs[c.i0],
             uv1 = mesh_.uvs.empty() ? Vec2(1, 0) : mesh_.uvs[c.i1],
             uv2 = mesh_.uvs.empty() ? Vec2(0, 1) : mesh_.uvs[c.i2];
  const Vec2 duv02 = uv0 - uv2, duv12 = uv1 - uv2;
  const Float4 dp02 = c.p0 - c.p2, dp12 = c.p1 - c.p2;
  const float det = duv02.x * duv12.y - duv02.y * duv12.x;
  if (det != 0 && std::isfinite(1 / det)) {
    si.dpdu = to_vec3((dp02 * duv12.y - dp12 * duv02.y) / det);
    si.dpdv = to_vec3((dp12 * duv02.x - dp02 * duv12.x) / det);
  } else {
    si.dpdu = to_vec3(c.p1 - c.p0);
    si.dpdv = to_vec3(c.p2 - c.p0);
  }
  si.shading = Frame::from_normal_and_tangent(sp.ns, si.dpdu);
  return si;
}

PositionSample TriangleMesh::sample_position(Vec2 u) const {
  if (!area_distribution_) return {};
  float u_reused = 0;
  const size_t tri = area_distribution_->sample(u.x, nullptr, &u_reused);
  const Vec2 b = square_to_uniform_triangle({u_reused, u.y});
  // Only the point, its error, normal and uv: no tangents or shading frame.
  const SurfacePoint sp = point_at(corners(unsigned(tri)), b.y, 1 - b.x - b.y);
  return {sp.p, sp.p_error, sp.ng, sp.uv, 1 / area_};
}

float TriangleMesh::boundary_test(const SurfaceInteraction& si, Vec3 d) const {
  if (!mesh_.normals.empty() && !mesh_.face_normals) {
    const float cosine = dot(si.shading.n, -d);
    return cosine * cosine;
  }
  const uint32_t* v = &mesh_.indices[size_t(si.prim) * 3];
  const Vec3 p0 = mesh_.positions[v[0]], e1 = mesh_.positions[v[1]] - p0, e2 = mesh_.positions[v[2]] - p0;
  const Vec3 q = si.p - p0;
  const double a = dot(e1, e1), b = dot(e1, e2), c = dot(e2, e2), det = a * c - b * b;
  if (!(det > 0)) return 0;
  const double qe1 = dot(q, e1), qe2 = dot(q, e2);
  const double b1 = (c * qe1 - b * qe2) / det, b2 = (a * qe2 - b * qe1) / det;
  return float(3 * std::clamp(std::min({1 - b1 - b2, b1, b2}), 0.0, 1.0 / 3));
}

}  // namespace caustica
