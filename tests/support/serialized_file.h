#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

// Mitsuba serialized files written field by field from the format's
// definition (little-endian; each mesh a 0x041C header, a version, then a
// zlib stream; a table of offsets at the end), compressed by zlib itself.
namespace caustica::test {

template <class T>
void put(std::string& out, T value) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  if (std::endian::native == std::endian::big) std::reverse(raw, raw + sizeof(T));
  out.append(raw, sizeof(T));
}

// One mesh as it is written: a unit quad in single precision unless changed.
struct MeshSpec {
  uint32_t flags = 0x1000;
  std::string name = "quad";
  std::vector<double> positions{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  std::vector<double> normals, uvs, colours;
  std::vector<uint32_t> indices{0, 1, 2, 0, 2, 3};
  uint64_t vertex_count = 4, triangle_count = 2;
};

std::string zlib_compress(const std::string& data);
// A mesh's fields before compression.
std::string serialized_payload(const MeshSpec& m, uint16_t version);
std::string serialized_file(const std::vector<MeshSpec>& meshes, uint16_t version = 4);

}  // namespace caustica::test
