#include "tests/support/serialized_file.h"

#include <zlib.h>

namespace caustica::test {

std::string zlib_compress(const std::string& data) {
  uLongf size = compressBound(uLong(data.size()));
  std::string out(size, '\0');
  compress2(reinterpret_cast<Bytef*>(out.data()), &size, reinterpret_cast<const Bytef*>(data.data()),
            uLong(data.size()), 9);
  out.resize(size);
  return out;
}

std::string serialized_payload(const MeshSpec& m, uint16_t version) {
  std::string out;
  put(out, m.flags);
  if (version == 4) out += m.name + '\0';
  put(out, m.vertex_count);
  put(out, m.triangle_count);
  for (const auto* values : {&m.positions, &m.normals, &m.uvs, &m.colours})
    for (double v : *values) (m.flags & 0x2000) ? put(out, v) : put(out, float(v));
  for (uint32_t i : m.indices) put(out, i);
  return out;
}

std::string serialized_file(const std::vector<MeshSpec>& meshes, uint16_t version) {
  std::string out;
  std::vector<uint64_t> offsets;
  for (const MeshSpec& m : meshes) {
    offsets.push_back(out.size());
    put(out, uint16_t(0x041C));
    put(out, version);
    out += zlib_compress(serialized_payload(m, version));
  }
  for (uint64_t o : offsets) version == 4 ? put(out, o) : put(out, uint32_t(o));
  put(out, uint32_t(meshes.size()));
  return out;
}

}  // namespace caustica::test
