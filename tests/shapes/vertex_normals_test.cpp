#include "core/shapes/vertex_normals.h"

#include <gtest/gtest.h>

#include <cmath>

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// Two triangles share vertex 0: one in the plane z = 0 (normal +z, a right
// angle at the vertex), one tilted (normal (1, 0, -1)/sqrt(2), an angle of
// acos(1/sqrt(3)) there). Weighted by angle, not by area (the second is the
// larger), the shared normal is their mean with those weights.
TEST(VertexNormals, AreMeansOfFaceNormalsWeightedByAngle) {
  MeshData mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 1}};
  mesh.indices = {0, 1, 2, 0, 2, 3};
  const auto normals = smooth_vertex_normals(mesh);
  ASSERT_EQ(normals.size(), 4u);
  const double a1 = M_PI / 2, a2 = std::acos(1 / std::sqrt(3.0)), h = 1 / std::sqrt(2.0);
  double expected[3] = {a2 * h, 0, a1 - a2 * h};
  const double length = std::sqrt(expected[0] * expected[0] + expected[2] * expected[2]);
  EXPECT_NEAR(normals[0].x, expected[0] / length, 1e-6);
  EXPECT_NEAR(normals[0].y, 0, 1e-6);
  EXPECT_NEAR(normals[0].z, expected[2] / length, 1e-6);
  // Vertex 1 lies in the flat triangle only, vertex 3 in the tilted one.
  EXPECT_NEAR(normals[1].z, 1, 1e-6);
  EXPECT_NEAR(normals[3].x, h, 1e-6);
  EXPECT_NEAR(normals[3].z, -h, 1e-6);
}

// A flat grid split into triangles of any shapes keeps the plane's normal.
TEST(VertexNormals, AFlatSurfaceKeepsItsNormal) {
  MeshData mesh;
  mesh.positions = {{0, 0, 0}, {3, 0, 0}, {3, 1, 0}, {0, 1, 0}, {1, 0.2f, 0}};
  mesh.indices = {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
  for (const Vec3& n : smooth_vertex_normals(mesh)) {
    EXPECT_NEAR(n.x, 0, 1e-6);
    EXPECT_NEAR(n.y, 0, 1e-6);
    EXPECT_NEAR(n.z, 1, 1e-6);
  }
}

// Two needles meet at vertex 0 with angles of 1e-14 and 2e-14 there, in
// the planes z = 0 and y = 0: the tiny angles are their weights, so
// the normal leans twice as far to the second's normal, (0, 1, 0), as to
// the first's, (0, 0, 1). An angle found as pi less the other two would be
// off by up to 2e-16 absolute, a hundredth of these.
TEST(VertexNormals, NeedleTrianglesKeepTheirTinyAnglesAsWeights) {
  MeshData mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1e-14f, 0}, {0, 0, 1}, {2e-14f, 0, 1}};
  mesh.indices = {0, 1, 2, 0, 3, 4};
  const auto normals = smooth_vertex_normals(mesh);
  const double a1 = std::atan2(double(1e-14f), 1.0), a2 = std::atan2(double(2e-14f), 1.0);
  const double length = std::sqrt(a1 * a1 + a2 * a2);
  EXPECT_NEAR(normals[0].x, 0, 1e-6);
  EXPECT_NEAR(normals[0].y, a2 / length, 1e-6);
  EXPECT_NEAR(normals[0].z, a1 / length, 1e-6);
}

TEST(VertexNormals, DegenerateTrianglesAndUnusedVerticesGiveZero) {
  MeshData mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {5, 5, 5}};
  mesh.indices = {0, 1, 2};
  for (const Vec3& n : smooth_vertex_normals(mesh)) EXPECT_EQ(squared_length(n), 0.0f);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
