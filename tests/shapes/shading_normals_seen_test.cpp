// Shading normals seen by the camera, against their definition computed in
// the test: at the point a camera ray meets a mesh with vertex normals, the
// normal is the barycentric interpolation (barycentrics found here from the
// hit position the aov layer reports) of the unit vertex normals, normalised.
// A mesh placed by its own to_world has its vertex normals taken to world
// space (by the inverse transpose, normalised) before they are
// interpolated; an instance interpolates in its group's space and carries
// the result, as Mitsuba does each, so under a non-uniform scale the two
// differ slightly. The same quad from an OBJ file, from a Mitsuba
// serialized file, scaled unevenly by its to_world and by an instance,
// each through the whole loader and Embree: a second oracle beside the
// mesh's own unit tests.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "tests/support/serialized_file.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using V3 = std::array<double, 3>;

const V3 kPositions[4] = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
const V3 kNormals[4] = {{-0.5, -0.5, 1}, {0.5, -0.3, 1}, {0.4, 0.6, 1}, {-0.6, 0.2, 1}};
const int kFaces[2][3] = {{0, 1, 2}, {0, 2, 3}};

V3 unit(V3 v) {
  const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / l, v[1] / l, v[2] / l};
}

std::filesystem::path obj_file() {
  const auto path = std::filesystem::temp_directory_path() / "caustica_shading_normals.obj";
  std::ofstream out(path);
  for (const V3& p : kPositions) out << "v " << p[0] << " " << p[1] << " " << p[2] << "\n";
  for (const V3& n : kNormals) out << "vn " << n[0] << " " << n[1] << " " << n[2] << "\n";
  for (const auto& f : kFaces)
    out << "f " << f[0] + 1 << "//" << f[0] + 1 << " " << f[1] + 1 << "//" << f[1] + 1 << " " << f[2] + 1 << "//"
        << f[2] + 1 << "\n";
  return path;
}

std::filesystem::path serialized() {
  test::MeshSpec m;
  m.flags = 0x1000 | 0x0001;  // single precision, with normals
  m.positions.clear();
  for (const V3& p : kPositions) m.positions.insert(m.positions.end(), p.begin(), p.end());
  for (const V3& n : kNormals) m.normals.insert(m.normals.end(), n.begin(), n.end());
  m.indices.clear();
  for (const auto& f : kFaces) m.indices.insert(m.indices.end(), {uint32_t(f[0]), uint32_t(f[1]), uint32_t(f[2])});
  const auto path = std::filesystem::temp_directory_path() / "caustica_shading_normals.serialized";
  std::ofstream(path, std::ios::binary) << test::serialized_file({m});
  return path;
}

// The world's (x, y) for local (x, y) under diag(sx, 1, 1): normals go by
// diag(1 / sx, 1, 1), per vertex or, for an instance, once interpolated.
void expect_normals(const std::string& shape, double sx, bool instance = false) {
  const auto scene = test::scene_from_xml(
      "<scene version='3.0.0'><integrator type='aov'><string name='aovs' value='p:position,n:sh_normal,"
      "i:prim_index'/></integrator><sensor type='perspective'><float name='fov' value='20'/><transform "
      "name='to_world'><lookat origin='0, 0, 4' target='0, 0, 0' up='0, 1, 0'/></transform><film type='hdrfilm'>"
      "<integer name='width' value='7'/><integer name='height' value='7'/><rfilter type='box'/></film>"
      "<sampler type='independent'><integer name='sample_count' value='1'/></sampler></sensor>" +
      shape + "</scene>");
  const auto image = test::render_scene(scene, 1).resolve();
  ASSERT_EQ(image.size(), 49u * 7);
  int hits = 0;
  for (int pixel = 0; pixel < 49; ++pixel) {
    const float* v = &image[pixel * 7];
    if (v[3] == 0 && v[4] == 0 && v[5] == 0) continue;  // the ray passed the quad
    ++hits;
    // Back to the mesh's own coordinates, where the barycentrics are found.
    const double x = v[0] / sx, y = v[1];
    const int* f = kFaces[int(v[6])];
    const V3 &a = kPositions[f[0]], &b = kPositions[f[1]], &c = kPositions[f[2]];
    const double det = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
    const double wb = ((x - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (y - a[1])) / det;
    const double wc = ((b[0] - a[0]) * (y - a[1]) - (x - a[0]) * (b[1] - a[1])) / det;
    const double wa = 1 - wb - wc;
    ASSERT_GE(std::min({wa, wb, wc}), -1e-4) << "pixel " << pixel << " is not on face " << v[6];
    V3 n{};
    const double w[3] = {wa, wb, wc};
    for (int k = 0; k < 3; ++k) {
      const V3 local = unit(kNormals[f[k]]);
      const V3 vertex = instance ? local : unit({local[0] / sx, local[1], local[2]});
      for (int i = 0; i < 3; ++i) n[i] += w[k] * vertex[i];
    }
    n = unit(instance ? V3{n[0] / sx, n[1], n[2]} : n);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(v[3 + i], n[i], 2e-4) << shape.substr(0, 40) << " pixel " << pixel;
  }
  EXPECT_GE(hits, 35);
}

TEST(ShadingNormalsSeen, ObjVertexNormals) {
  expect_normals("<shape type='obj'><string name='filename' value='" + obj_file().string() + "'/></shape>", 1);
}

TEST(ShadingNormalsSeen, SerializedVertexNormals) {
  expect_normals("<shape type='serialized'><string name='filename' value='" + serialized().string() + "'/></shape>", 1);
}

TEST(ShadingNormalsSeen, AMeshScaledUnevenly) {
  expect_normals("<shape type='obj'><string name='filename' value='" + obj_file().string() +
                     "'/><transform name='to_world'><scale x='0.6' y='1' z='1'/></transform></shape>",
                 0.6);
}

TEST(ShadingNormalsSeen, AnInstanceScaledUnevenly) {
  expect_normals("<shape type='shapegroup' id='g'><shape type='obj'><string name='filename' value='" +
                     obj_file().string() +
                     "'/></shape></shape><shape type='instance'><ref id='g'/><transform name='to_world'>"
                     "<scale x='0.6' y='1' z='1'/></transform></shape>",
                 0.6, true);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
