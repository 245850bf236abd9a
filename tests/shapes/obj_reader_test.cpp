#include "core/shapes/obj_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/errors/interrupted.h"
#include "tests/support/thrown_message.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using ::testing::HasSubstr;

std::string obj_error(const std::string& text) {
  return test::thrown_message<ObjError>([&] { read_obj(text); });
}

std::vector<uint32_t> indices(std::initializer_list<uint32_t> list) { return list; }

// A pentagon of v/vt/vn corners becomes a fan of three triangles over five
// vertices; a two-corner face adds nothing.
TEST(ObjReader, ReadsPolygonsAsFansWithNormalsAndTextureCoordinates) {
  const MeshData mesh = read_obj(
      "# a pentagon\r\nmtllib none.mtl\r\no thing\r\nv 0 0 0\r\nv 1 0 0\r\nv 1.5 1 0\r\nv 0.5 2 0\r\nv -0.5 1 0\r\n"
      "vt 0 0\r\nvt 1 0\r\nvt 1 1\r\nvt 0 1\r\nvt 0.5 0.5\r\nvn 0 0 1\r\nusemtl none\r\ns 1\r\n"
      "f 1/1/1 2/2/1 3/3/1 4/4/1 5/5/1\r\nf 1/1/1 2/2/1\r\n");
  ASSERT_EQ(mesh.positions.size(), 5u);
  EXPECT_EQ(mesh.positions[2].x, 1.5f);
  EXPECT_EQ(mesh.positions[3].y, 2.0f);
  EXPECT_EQ(mesh.indices, indices({0, 1, 2, 0, 2, 3, 0, 3, 4}));
  ASSERT_EQ(mesh.normals.size(), 5u);
  EXPECT_EQ(mesh.normals[4].z, 1.0f);
  ASSERT_EQ(mesh.uvs.size(), 5u);
  EXPECT_EQ(mesh.uvs[4].x, 0.5f);
  EXPECT_EQ(mesh.uvs[2].y, 1.0f);
}

// Corners sharing a position, texture coordinate and normal share a vertex
// (so smooth normals can be computed across faces); a position met with
// two normals (a hard edge) becomes two vertices. Objects and groups all
// go into the one mesh; relative (negative) indices count back from the
// last vertex defined.
TEST(ObjReader, SharesVerticesByTheirWholeCornerAndResolvesRelativeIndices) {
  const MeshData roof = read_obj(
      "v -1 -1 -1\nv 0 -1 0\nv 0 1 0\nv -1 1 -1\nv 1 -1 -1\nv 1 1 -1\ng left\nf 1 2 3 4\ng right\nf -5 -2 -1 -4\n");
  EXPECT_EQ(roof.positions.size(), 6u);
  EXPECT_EQ(roof.indices, indices({0, 1, 2, 0, 2, 3, 1, 4, 5, 1, 5, 2}));
  EXPECT_TRUE(roof.normals.empty());
  EXPECT_TRUE(roof.uvs.empty());

  const MeshData hard = read_obj(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvn 0 0 1\nvn 0 1 0\n"
      "o a\nf 1//1 2//1 3//1\no b\nf 1//2 4//2 2//2\n");
  EXPECT_EQ(hard.positions.size(), 6u);
  EXPECT_EQ(hard.indices, indices({0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(hard.normals[3].y, 1.0f);
}

// Normals or texture coordinates that only some corners name cannot be
// interpolated over the mesh: they are dropped, the other attribute kept.
TEST(ObjReader, AttributesSomeCornersLackAreDropped) {
  const MeshData mesh = read_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\nf 1/1/1 2//1 3//1\n");
  EXPECT_EQ(mesh.positions.size(), 3u);
  EXPECT_EQ(mesh.normals.size(), 3u);
  EXPECT_TRUE(mesh.uvs.empty());
}

TEST(ObjReader, IndicesOutsideTheFileAreRefusedWithTheirLine) {
  const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n";
  EXPECT_EQ(obj_error(triangle + "f 1 2 3\nf 1 2\n\nf 1 2 9\n"),
            "line 9: face refers to vertex 9 (counting from 1), but the file defines 3");
  EXPECT_EQ(obj_error(triangle + "f 1 2 -4\n"),
            "line 6: face refers to vertex 0 (counting from 1), but the file defines 3");
  EXPECT_EQ(obj_error(triangle + "f 1/1 2/2 3/1\n"),
            "line 6: face refers to texture coordinate 2 (counting from 1), but the file defines 1");
  EXPECT_EQ(obj_error(triangle + "  f 1//1 2//1 3//3\n"),
            "line 6: face refers to normal 3 (counting from 1), but the file defines 1");
  EXPECT_THAT(obj_error(triangle + "f 1 0 2\n"), HasSubstr("line 6"));
}

TEST(ObjReader, AStopRequestInterruptsTheRead) {
  stop_request().store(true);
  EXPECT_THROW(read_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), Interrupted);
  stop_request().store(false);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
