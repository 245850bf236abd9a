// A triangle's hit interaction and area samples against values worked out
// here in double precision: the point lies within its error bound of the
// exact barycentric point, the geometric normal is the unit cross product
// of the edges turned toward the interpolated vertex normal, the shading
// normal is the interpolation of the unit vertex normals, normalised, uv
// and the tangents follow the vertex uvs, and flip_normals turns both
// normals over.

#include "core/shapes/triangle_mesh.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using Vec3d = std::array<double, 3>;

Vec3d to_double(Vec3 v) { return {v.x, v.y, v.z}; }
Vec3d minus(Vec3d a, Vec3d b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3d unit(Vec3d v) {
  const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / l, v[1] / l, v[2] / l};
}
Vec3d cross_d(Vec3d a, Vec3d b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3d blend(const std::array<Vec3d, 3>& v, double b1, double b2) {
  const double b0 = 1 - b1 - b2;
  Vec3d out;
  for (int i = 0; i < 3; ++i) out[i] = b0 * v[0][i] + b1 * v[1][i] + b2 * v[2][i];
  return out;
}

void expect_near(Vec3 actual, Vec3d expected, double tolerance) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(actual[i], expected[i], tolerance) << "component " << i;
}

// The vertex normals point to -z-ish while the winding's normal is +z-ish:
// the geometric normal must follow the vertex normals.
MeshData tilted_triangle() {
  MeshData mesh;
  mesh.positions = {{1.5f, -0.25f, 2.0f}, {4.0f, 0.5f, 2.5f}, {2.0f, 3.0f, 1.75f}};
  mesh.normals = {{0.1f, 0.2f, -1.0f}, {-0.3f, 0.1f, -0.9f}, {0.2f, -0.4f, -0.8f}};
  mesh.uvs = {{0.25f, 0.5f}, {2.0f, 0.75f}, {0.5f, 3.0f}};
  mesh.indices = {0, 1, 2};
  return mesh;
}

TEST(TriangleMesh, HitInteractionMatchesTheTriangleWorkedOutInDouble) {
  for (const bool flip : {false, true}) {
    const MeshData mesh = tilted_triangle();
    const TriangleMesh shape(mesh, Transform(), flip, "test");
    const float b1 = 0.3f, b2 = 0.45f;
    RayHit hit;
    hit.t = 2;
    hit.uv = {b1, b2};
    const SurfaceInteraction si = shape.interaction(Ray{}, hit);

    const std::array<Vec3d, 3> p{to_double(mesh.positions[0]), to_double(mesh.positions[1]),
                                 to_double(mesh.positions[2])};
    const Vec3d exact = blend(p, b1, b2);
    for (int i = 0; i < 3; ++i) {
      EXPECT_LE(std::abs(si.p[i] - exact[i]), si.p_error[i]) << "component " << i;
      EXPECT_LT(si.p_error[i], 1e-5) << "component " << i;
    }

    const double sign = flip ? -1 : 1;
    // Vertex normals are directions: the mesh keeps them at unit length.
    const Vec3d ns = unit(
        blend({unit(to_double(mesh.normals[0])), unit(to_double(mesh.normals[1])), unit(to_double(mesh.normals[2]))},
              b1, b2));
    expect_near(si.shading.n, {sign * ns[0], sign * ns[1], sign * ns[2]}, 1e-6);
    const Vec3d winding = unit(cross_d(minus(p[1], p[0]), minus(p[2], p[0])));
    // The winding's normal faces away from the vertex normals: ng is its opposite.
    ASSERT_LT(winding[0] * ns[0] + winding[1] * ns[1] + winding[2] * ns[2], 0);
    expect_near(si.ng, {-sign * winding[0], -sign * winding[1], -sign * winding[2]}, 1e-6);

    const double b0 = 1 - b1 - b2;
    EXPECT_NEAR(si.uv.x, b0 * 0.25 + b1 * 2.0 + b2 * 0.5, 1e-6);
    EXPECT_NEAR(si.uv.y, b0 * 0.5 + b1 * 0.75 + b2 * 3.0, 1e-6);
    // p(u, v) is affine: its tangents map the uv edges onto the position edges.
    const double du1 = 2.0 - 0.25, dv1 = 0.75 - 0.5, du2 = 0.5 - 0.25, dv2 = 3.0 - 0.5;
    const Vec3d e1 = minus(p[1], p[0]), e2 = minus(p[2], p[0]);
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(si.dpdu[i] * du1 + si.dpdv[i] * dv1, e1[i], 1e-5) << "component " << i;
      EXPECT_NEAR(si.dpdu[i] * du2 + si.dpdv[i] * dv2, e2[i], 1e-5) << "component " << i;
    }
    EXPECT_EQ(si.t, 2);
    EXPECT_EQ(si.shape, &shape);
  }
}

// Without vertex normals or uvs: ng is the winding's normal (flipped on
// request), uv the barycentrics, and the tangents the edges from vertex 0.
TEST(TriangleMesh, BareTriangleUsesItsWindingAndBarycentrics) {
  for (const bool flip : {false, true}) {
    MeshData mesh = tilted_triangle();
    mesh.normals.clear();
    mesh.uvs.clear();
    const TriangleMesh shape(mesh, Transform(), flip, "test");
    RayHit hit;
    hit.uv = {0.2f, 0.7f};
    const SurfaceInteraction si = shape.interaction(Ray{}, hit);
    const std::array<Vec3d, 3> p{to_double(mesh.positions[0]), to_double(mesh.positions[1]),
                                 to_double(mesh.positions[2])};
    const Vec3d winding = unit(cross_d(minus(p[1], p[0]), minus(p[2], p[0])));
    const double sign = flip ? -1 : 1;
    expect_near(si.ng, {sign * winding[0], sign * winding[1], sign * winding[2]}, 1e-6);
    expect_near(si.shading.n, {sign * winding[0], sign * winding[1], sign * winding[2]}, 1e-6);
    EXPECT_FLOAT_EQ(si.uv.x, 0.2f);
    EXPECT_FLOAT_EQ(si.uv.y, 0.7f);
    expect_near(si.dpdu, minus(p[1], p[0]), 1e-5);
    expect_near(si.dpdv, minus(p[2], p[0]), 1e-5);
  }
}

// Area samples land on the triangle, carry its normal and 1 / area.
TEST(TriangleMesh, AreaSamplesLieOnTheTriangle) {
  const MeshData mesh = tilted_triangle();
  const TriangleMesh shape(mesh, Transform(), false, "test");
  const std::array<Vec3d, 3> p{to_double(mesh.positions[0]), to_double(mesh.positions[1]),
                               to_double(mesh.positions[2])};
  const Vec3d c = cross_d(minus(p[1], p[0]), minus(p[2], p[0]));
  const double area = 0.5 * std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  const Vec3d winding = unit(c);
  for (const Vec2 u : {Vec2(0.1f, 0.2f), Vec2(0.5f, 0.5f), Vec2(0.9f, 0.05f), Vec2(0.33f, 0.97f)}) {
    const PositionSample ps = shape.sample_position(u);
    EXPECT_NEAR(ps.pdf, 1 / area, 1e-6 / area);
    // On the plane within the error bound, and inside every edge.
    const Vec3d q = minus(to_double(ps.p), p[0]);
    const double error =
        std::abs(winding[0]) * ps.p_error.x + std::abs(winding[1]) * ps.p_error.y + std::abs(winding[2]) * ps.p_error.z;
    EXPECT_LE(std::abs(q[0] * winding[0] + q[1] * winding[1] + q[2] * winding[2]), error);
    for (int e = 0; e < 3; ++e) {
      const Vec3d edge = minus(p[(e + 1) % 3], p[e]), to_q = minus(to_double(ps.p), p[e]);
      const Vec3d side = cross_d(edge, to_q);
      EXPECT_GE(side[0] * winding[0] + side[1] * winding[1] + side[2] * winding[2], -1e-5) << "edge " << e;
    }
    // The vertex normals face away from the winding: so does the sample's normal.
    expect_near(ps.n, {-winding[0], -winding[1], -winding[2]}, 1e-6);
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
