#include "core/shapes/serialized_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "core/errors/interrupted.h"
#include "tests/support/serialized_file.h"
#include "tests/support/thrown_message.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using test::MeshSpec;
using test::put;
using test::serialized_payload;
using test::zlib_compress;
using ::testing::HasSubstr;

std::string file(const std::vector<MeshSpec>& meshes, uint16_t version = 4) {
  return test::serialized_file(meshes, version);
}

std::string serialized_error(const std::string& bytes, uint64_t index = 0) {
  return test::thrown_message<SerializedError>([&] { read_serialized(bytes, index); });
}

MeshSpec rich_triangle() {
  MeshSpec m;
  m.flags = 0x2000 | 0x0001 | 0x0002 | 0x0008;
  m.name = "";
  m.positions = {1e-3, 2, 3, 4, 5.5, 6, 7, 8, 9.25};
  m.normals = {0, 0, 1, 0, 1, 0, 1, 0, 0};
  m.uvs = {0, 0, 1, 0, 0.5, 1};
  m.colours = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  m.indices = {2, 1, 0};
  m.vertex_count = 3;
  m.triangle_count = 1;
  return m;
}

TEST(SerializedReader, ReadsEachMeshOfAFileInBothVersions) {
  for (uint16_t version : {uint16_t(3), uint16_t(4)}) {
    const std::string bytes = file({MeshSpec(), rich_triangle()}, version);
    const MeshData quad = read_serialized(bytes, 0);
    ASSERT_EQ(quad.positions.size(), 4u);
    EXPECT_EQ(quad.positions[2].x, 1.0f);
    EXPECT_EQ(quad.positions[2].y, 1.0f);
    EXPECT_TRUE(quad.normals.empty());
    EXPECT_TRUE(quad.uvs.empty());
    EXPECT_EQ(quad.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));

    // Double precision, with normals, texture coordinates and colours (skipped).
    const MeshData triangle = read_serialized(bytes, 1);
    ASSERT_EQ(triangle.positions.size(), 3u);
    EXPECT_EQ(triangle.positions[0].x, 1e-3f);
    EXPECT_EQ(triangle.positions[1].y, 5.5f);
    EXPECT_EQ(triangle.positions[2].z, 9.25f);
    ASSERT_EQ(triangle.normals.size(), 3u);
    EXPECT_EQ(triangle.normals[1].y, 1.0f);
    EXPECT_EQ(triangle.normals[2].x, 1.0f);
    ASSERT_EQ(triangle.uvs.size(), 3u);
    EXPECT_EQ(triangle.uvs[2].x, 0.5f);
    EXPECT_EQ(triangle.uvs[2].y, 1.0f);
    EXPECT_EQ(triangle.indices, (std::vector<uint32_t>{2, 1, 0}));
  }
}

// The first mesh is read without the table (as Mitsuba reads it), so a file
// written without one still loads.
TEST(SerializedReader, TheFirstMeshNeedsNoTable) {
  std::string bytes;
  put(bytes, uint16_t(0x041C));
  put(bytes, uint16_t(4));
  bytes += zlib_compress(serialized_payload(MeshSpec(), 4));
  EXPECT_EQ(read_serialized(bytes, 0).indices.size(), 6u);
}

TEST(SerializedReader, TheFaceNormalFlagDropsVertexNormals) {
  MeshSpec m = rich_triangle();
  m.flags |= 0x0010;
  const MeshData mesh = read_serialized(file({m}), 0);
  EXPECT_TRUE(mesh.face_normals);
  EXPECT_TRUE(mesh.normals.empty());
  EXPECT_EQ(mesh.uvs.size(), 3u);
  EXPECT_EQ(mesh.indices, (std::vector<uint32_t>{2, 1, 0}));
}

// The first mesh needs only its own bytes; the second needs the table too.
TEST(SerializedReader, EveryTruncationIsAnErrorNotACrash) {
  const std::string bytes = file({MeshSpec(), rich_triangle()});
  const size_t first_mesh = file({MeshSpec()}).size() - 12;
  for (size_t n = 0; n < bytes.size(); ++n) {
    if (n < first_mesh) {
      EXPECT_NE(serialized_error(bytes.substr(0, n), 0), "no error") << n;
    }
    EXPECT_NE(serialized_error(bytes.substr(0, n), 1), "no error") << n;
  }
}

TEST(SerializedReader, BadFilesGetErrorsNamingTheMeshAndWhy) {
  EXPECT_EQ(serialized_error("\x1c\x04"), "the file is shorter than the 4-byte header of a serialized mesh");
  EXPECT_EQ(serialized_error("PK\x03\x04 zip"), "not a serialized mesh: byte 0 starts with 0x4b50, not 0x041c");
  std::string v5 = file({MeshSpec()});
  v5[2] = 5;
  EXPECT_EQ(serialized_error(v5), "format version 5 is not 3 or 4");

  const std::string two = file({MeshSpec(), MeshSpec()});
  EXPECT_EQ(serialized_error(two, 2), "shape_index 2 is out of range: the file holds 2 meshes");
  std::string many = two;
  many[many.size() - 4] = 100;
  EXPECT_EQ(serialized_error(many, 1), "its table claims 100 meshes, more than the file can hold");
  std::string outside = two;
  outside[outside.size() - 12] = char(0xff);
  EXPECT_THAT(serialized_error(outside, 1), HasSubstr("mesh 1 is placed at byte "));
  EXPECT_THAT(serialized_error(outside, 1), HasSubstr(", outside the file's "));

  std::string damaged = file({MeshSpec()});
  damaged[4] = 0x12;  // the zlib header's first byte
  EXPECT_THAT(serialized_error(damaged), HasSubstr("mesh 0: the compressed data is damaged (zlib: "));

  const std::string one = file({MeshSpec()});
  EXPECT_EQ(serialized_error(one.substr(0, one.size() - 13)),
            "mesh 0 ('quad'): the compressed data ends before its checksum");

  MeshSpec short_indices;
  short_indices.indices.pop_back();
  EXPECT_EQ(serialized_error(file({short_indices})),
            "mesh 0 ('quad'): the data ends after 93 uncompressed bytes, in the triangles");

  MeshSpec out_of_range;
  out_of_range.indices[4] = 7;
  EXPECT_EQ(serialized_error(file({out_of_range})),
            "mesh 0 ('quad'): triangle 1 refers to vertex 7, but the mesh has 4 vertices");

  MeshSpec infinite = rich_triangle();
  infinite.positions[7] = 1e39;  // finite in double, not in float
  EXPECT_EQ(serialized_error(file({infinite})), "mesh 0: vertex 2 has a position value that is not finite in float");

  MeshSpec huge;
  huge.vertex_count = 4000000000;
  EXPECT_THAT(serialized_error(file({huge})),
              HasSubstr("mesh 0 ('quad'): 4000000000 vertices and 2 triangles need more data than its "));
  MeshSpec too_many;
  too_many.vertex_count = uint64_t(1) << 32;
  EXPECT_EQ(serialized_error(file({too_many})), "mesh 0 ('quad'): 4294967296 vertices are more than 2^32 - 1");

  MeshSpec both;
  both.flags = 0x3000;
  EXPECT_EQ(serialized_error(file({both})), "mesh 0: its flags ask for both single and double precision");
  MeshSpec long_name;
  long_name.name = std::string(70000, 'n');
  EXPECT_EQ(serialized_error(file({long_name})), "mesh 0: its name runs past 65536 bytes");
}

TEST(SerializedReader, AStopRequestInterruptsTheRead) {
  const std::string bytes = file({MeshSpec()});
  stop_request().store(true);
  EXPECT_THROW(read_serialized(bytes, 0), Interrupted);
  stop_request().store(false);
  EXPECT_EQ(read_serialized(bytes, 0).indices.size(), 6u);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
