#include "core/shapes/ply_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <bit>
#include <cstring>

#include "core/errors/interrupted.h"
#include "tests/support/thrown_message.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using ::testing::HasSubstr;

const std::string kTriangleHeader =
    "ply\nformat ascii 1.0\ncomment made by hand\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";

std::string ply_error(const std::string& bytes) {
  return test::thrown_message<PlyError>([&] { read_ply(bytes); });
}

TEST(PlyReader, ReadsAsciiPolygonsAsFansWithNormalsAndTextureCoordinates) {
  const MeshData mesh = read_ply(
      "ply\r\nformat ascii 1.0\r\nelement vertex 4\r\nproperty float x\r\nproperty float y\r\nproperty float z\r\n"
      "property float nx\r\nproperty float ny\r\nproperty float nz\r\nproperty float s\r\nproperty float t\r\n"
      "property list uchar float extra\r\nelement face 1\r\nproperty uchar flags\r\n"
      "property list uchar uint vertex_index\r\nelement edge 1\r\nproperty int a\r\nend_header\r\n"
      "0 0 0 0 0 1 0 0 2 9 9\r\n1 0 0 0 0 1 1 0 0\r\n1 1 0 0 0 1 1 1 0\r\n0 1 +0 0 0 1 0 1 1 7.5\r\n"
      "5 4 0 1 2 3\r\n0 1\r\n");
  ASSERT_EQ(mesh.positions.size(), 4u);
  EXPECT_EQ(mesh.positions[2].x, 1.0f);
  EXPECT_EQ(mesh.positions[2].y, 1.0f);
  ASSERT_EQ(mesh.normals.size(), 4u);
  EXPECT_EQ(mesh.normals[3].z, 1.0f);
  ASSERT_EQ(mesh.uvs.size(), 4u);
  EXPECT_EQ(mesh.uvs[3].y, 1.0f);
  EXPECT_EQ(mesh.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
}

// Little- and big-endian files are written here byte by byte, so the
// reader's byte order is checked against the format's definition.
template <class T>
void put(std::string& out, T value, bool big_endian) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  if (big_endian != (std::endian::native == std::endian::big)) std::reverse(raw, raw + sizeof(T));
  out.append(raw, sizeof(T));
}

std::string binary_quad(bool big_endian) {
  std::string out = std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
                    " 1.0\nelement vertex 4\nproperty double x\nproperty float y\nproperty float z\n"
                    "property short extra\nelement face 2\nproperty list int ushort vertex_indices\nend_header\n";
  const float corners[4][2] = {{0, 0}, {2, 0}, {2, 3}, {0, 3}};
  for (const auto& c : corners) {
    put<double>(out, c[0], big_endian);
    put<float>(out, c[1], big_endian);
    put<float>(out, -1.5f, big_endian);
    put<int16_t>(out, -7, big_endian);
  }
  put<int32_t>(out, 3, big_endian);
  for (uint16_t i : {0, 1, 2}) put<uint16_t>(out, i, big_endian);
  put<int32_t>(out, 3, big_endian);
  for (uint16_t i : {0, 2, 3}) put<uint16_t>(out, i, big_endian);
  return out;
}

TEST(PlyReader, ReadsBothBinaryByteOrders) {
  for (bool big_endian : {false, true}) {
    const MeshData mesh = read_ply(binary_quad(big_endian));
    ASSERT_EQ(mesh.positions.size(), 4u) << big_endian;
    EXPECT_EQ(mesh.positions[2].x, 2.0f);
    EXPECT_EQ(mesh.positions[2].y, 3.0f);
    EXPECT_EQ(mesh.positions[2].z, -1.5f);
    EXPECT_TRUE(mesh.normals.empty());
    EXPECT_TRUE(mesh.uvs.empty());
    EXPECT_EQ(mesh.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3})) << big_endian;
  }
}

// Each binary type keeps its sign and width: vertices whose coordinates
// are stored as signed and unsigned integers of every size.
TEST(PlyReader, ReadsEveryBinaryTypeWithItsSignInBothByteOrders) {
  for (bool big_endian : {false, true}) {
    std::string out = std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
                      " 1.0\nelement vertex 2\nproperty char x\nproperty short y\nproperty int z\n"
                      "property uchar u\nproperty ushort v\nproperty uint extra\nend_header\n";
    for (int sign : {-1, 1}) {
      put<int8_t>(out, int8_t(sign * 100), big_endian);
      put<int16_t>(out, int16_t(sign * 30000), big_endian);
      put<int32_t>(out, sign * 2000000000, big_endian);
      put<uint8_t>(out, 200, big_endian);
      put<uint16_t>(out, 60000, big_endian);
      put<uint32_t>(out, 4000000000u, big_endian);
    }
    const MeshData mesh = read_ply(out);
    ASSERT_EQ(mesh.positions.size(), 2u) << big_endian;
    for (int i : {0, 1}) {
      const float sign = i == 0 ? -1 : 1;
      EXPECT_EQ(mesh.positions[i].x, sign * 100) << big_endian;
      EXPECT_EQ(mesh.positions[i].y, sign * 30000) << big_endian;
      EXPECT_EQ(mesh.positions[i].z, sign * 2e9f) << big_endian;
      ASSERT_EQ(mesh.uvs.size(), 2u);
      EXPECT_EQ(mesh.uvs[i].x, 200) << big_endian;
      EXPECT_EQ(mesh.uvs[i].y, 60000) << big_endian;
    }
  }
}

TEST(PlyReader, EveryTruncationOfABinaryFileIsAnErrorNotACrash) {
  const std::string whole = binary_quad(false);
  for (size_t n = 0; n < whole.size(); ++n) EXPECT_NE(ply_error(whole.substr(0, n)), "no error") << n;
}

TEST(PlyReader, BadFilesGetErrorsNamingWhereAndWhy) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"solid cube\n", "line 1: not a PLY file (it does not start with 'ply')"},
      {"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x", "line 4: the header has no end_header line"},
      {"ply\nformat utf8 1.0\n", "line 2: unknown format 'utf8'"},
      {"ply\nelement vertex 0\nend_header\n", "line 2: the header names no format"},
      {"ply\nformat ascii 1.0\nelement vertex -3\n", "line 3: element 'vertex' has count '-3', not a non-negative"},
      {"ply\nformat ascii 1.0\nproperty float x\n", "line 3: a property before any element"},
      {"ply\nformat ascii 1.0\nelement vertex 1\nproperty half x\n", "line 4: unknown type 'half'"},
      {"ply\nformat ascii 1.0\nelement face 1\nproperty list float int vertex_indices\n",
       "line 4: a list's count must have an integer type"},
      {"ply\nformat ascii 1.0\nend_header\n", "the file has no vertex element"},
      {"ply\nformat ascii 1.0\nelement vertex 0\nelement vertex 0\nend_header\n", "the file has two vertex elements"},
      {"ply\nformat ascii 1.0\nelement vertex 3\nend_header\n", "the vertex element has no x, y and z properties"},
      {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n0 0\n",
       "the vertex element has no x, y and z properties"},
      {"ply\nformat ascii 1.0\nelement vertex 5000000000\nproperty float x\nend_header\n",
       "declares 5000000000 vertices, more than 2^32 - 1"},
      {"ply\nformat binary_little_endian 1.0\nelement vertex 4000000\nproperty float x\nproperty float y\n"
       "property float z\nend_header\n0123456789",
       "byte 121: element 'vertex' declares 4000000 items, more than the 10 bytes left can hold"},
      {kTriangleHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n",
       "line 14: face 0 refers to vertex 7, but the mesh has 3 vertices"},
      {kTriangleHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n",
       "line 14: face 0 refers to vertex -1, but the mesh has 3 vertices"},
      {kTriangleHeader + "0 0 0\n1 0 0\n0 1 0\n200 0 1 2\n",
       "line 14: a list of 200 items in face 0 does not fit in the rest of the file"},
      {kTriangleHeader + "0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n", "line 12: 'zero' is not a number"},
      {kTriangleHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 1.5 2\n", "line 14: '1.5' is not an integer"},
      {kTriangleHeader + "0 0 0\n1 0 0\n0 1e39 0\n3 0 1 2\n", "vertex 2 has a value that is not finite in float"},
      {kTriangleHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 1 ", "line 14: the file ends in the middle of the data"},
  };
  for (const auto& [file, message] : cases) EXPECT_THAT(ply_error(file), HasSubstr(message)) << file;
}

TEST(PlyReader, QuotesOnlyAShortExcerptOfAHugeValue) {
  const std::string error = ply_error("ply\nformat ascii 1.0\nelement vertex " + std::string(100000, '9') + "x\n");
  EXPECT_LT(error.size(), 200u) << error;
  EXPECT_THAT(error, HasSubstr("9999..."));
}

TEST(PlyReader, AStopRequestInterruptsTheRead) {
  stop_request().store(true);
  EXPECT_THROW(read_ply(kTriangleHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"), Interrupted);
  stop_request().store(false);
  EXPECT_EQ(read_ply(kTriangleHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n").indices.size(), 3u);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
