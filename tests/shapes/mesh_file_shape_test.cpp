// The mesh-file shapes as a scene uses them: which mesh of a serialized
// file, and the normals a mesh is shaded with.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <utility>

#include "core/registry/properties.h"
#include "tests/support/serialized_file.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

// A serialized file's second mesh, placed by to_world; a negative or
// missing index is refused with the file named.
TEST(MeshFileShape, SerializedMeshesAreLoadedByIndex) {
  const fs::path path = fs::temp_directory_path() / "caustica_two_meshes.serialized";
  test::MeshSpec big_quad;
  big_quad.positions = {0, 0, 0, 2, 0, 0, 2, 2, 0, 0, 2, 0};
  std::ofstream(path, std::ios::binary) << test::serialized_file({test::MeshSpec(), big_quad});
  const auto shape = [&](const std::string& index) {
    return "<scene version='3.0.0'><shape type='serialized'><string name='filename' value='" + path.string() +
           "'/><integer name='shape_index' value='" + index +
           "'/><transform name='to_world'><translate z='-3'/></transform></shape></scene>";
  };
  const auto scene = test::scene_from_xml(shape("1"));
  ASSERT_EQ(scene->shapes().size(), 1u);
  EXPECT_FLOAT_EQ(scene->shapes()[0]->area(), 4);
  const auto hit = scene->intersect({scene->render_point({1.5, 1.5, 1}), {0, 0, -1}});
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 4, 1e-5f);
  EXPECT_THAT(test::load_error(shape("-1")),
              HasSubstr("test.xml:1: parameter 'shape_index' of shape 'serialized': must not be negative"));
  EXPECT_THAT(test::load_error(shape("2")),
              HasSubstr("test.xml:1: parameter 'filename' of shape 'serialized': mesh file '" + path.string() +
                        "': shape_index 2 is out of range: the file holds 2 meshes"));
}

// A roof of two faces meeting at a right angle along x = 0, in a PLY and an
// OBJ file without normals: shaded smooth (the ridge's normal straight up,
// halfway between the faces' normals), as Mitsuba shades it, or flat with
// face_normals.
TEST(MeshFileShape, MeshesWithoutNormalsAreShadedSmoothUnlessFaceNormalsAsked) {
  const fs::path ply = fs::temp_directory_path() / "caustica_roof.ply";
  std::ofstream(ply) << "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\n"
                        "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n"
                        "-1 -1 -1\n0 -1 0\n0 1 0\n-1 1 -1\n1 -1 -1\n1 1 -1\n"
                        "4 0 1 2 3\n4 1 4 5 2\n";
  const fs::path obj = fs::temp_directory_path() / "caustica_roof.obj";
  std::ofstream(obj) << "v -1 -1 -1\nv 0 -1 0\nv 0 1 0\nv -1 1 -1\nv 1 -1 -1\nv 1 1 -1\nf 1 2 3 4\nf 2 5 6 3\n";
  for (const auto& [type, path] : {std::pair("ply", ply), std::pair("obj", obj)}) {
    const auto shading_normal = [&](const std::string& extra) {
      const auto scene = test::scene_from_xml("<scene version='3.0.0'><shape type='" + std::string(type) +
                                              "'><string name='filename' value='" + path.string() + "'/>" + extra +
                                              "</shape></scene>");
      // Just left of the ridge, on the face whose normal is (-1, 0, 1)/sqrt(2).
      const Vec3 o = scene->render_point({-0.01, 0, 5});
      const auto hit = scene->intersect({o, {0, 0, -1}});
      EXPECT_TRUE(hit);
      return hit ? hit->shading.n : Vec3();
    };
    const Vec3 smooth = shading_normal("");
    // 1% of the way from the ridge (normal +z) to the eave (the face's normal).
    EXPECT_NEAR(smooth.x, -0.01 / std::sqrt(2.0), 2e-4) << type;
    EXPECT_GT(smooth.z, 0.999) << type;
    const Vec3 flat = shading_normal("<boolean name='face_normals' value='true'/>");
    EXPECT_NEAR(flat.x, -1 / std::sqrt(2.0), 1e-6) << type;
    EXPECT_NEAR(flat.z, 1 / std::sqrt(2.0), 1e-6) << type;
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
