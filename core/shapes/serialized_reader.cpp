#include "core/shapes/serialized_reader.h"

#include <zlib.h>

#include <bit>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/errors/interrupted.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

constexpr uint16_t kFormat = 0x041C;
constexpr uint32_t kHasNormals = 0x0001, kHasTexcoords = 0x0002, kHasColors = 0x0008, kFaceNormals = 0x0010,
                   kSinglePrecision = 0x1000, kDoublePrecision = 0x2000;
// DEFLATE expands a byte into at most about 1032; counts that need more
// output than the compressed bytes can give are refused unallocated.
constexpr uint64_t kMaxExpansion = 1032;
constexpr size_t kMaxNameBytes = 1 << 16;
constexpr size_t kChunkBytes = 1 << 20;

uint64_t load_le(const char* p, int bytes) {
  uint64_t v = 0;
  for (int i = bytes - 1; i >= 0; --i) v = v << 8 | uint8_t(p[i]);
  return v;
}

std::string hex4(uint64_t v) {
  static const char digits[] = "0123456789abcdef";
  std::string s = "0x0000";
  for (int i = 0; i < 4; ++i) s[5 - i] = digits[(v >> (4 * i)) & 15];
  return s;
}

// One mesh's zlib stream, inflated on demand. Errors begin with `context`,
// which may grow as the mesh's name is read.
class Inflater {
 public:
  Inflater(std::string_view compressed, const std::string& context) : context_(context) {
    stream_.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(compressed.data()));
    stream_.avail_in = uInt(std::min<size_t>(compressed.size(), std::numeric_limits<uInt>::max()));
    if (inflateInit(&stream_) != Z_OK) throw SerializedError(context_ + ": zlib could not start");
  }
  ~Inflater() { inflateEnd(&stream_); }
  Inflater(const Inflater&) = delete;
  Inflater& operator=(const Inflater&) = delete;

  // Fills dst with the next n bytes of the stream; throws if it ends sooner.
  void read(char* dst, size_t n, const char* what) {
    size_t done = 0;
    while (done < n) {
      if (stop_request().load()) throw Interrupted("interrupted");
      const size_t want = std::min(n - done, kChunkBytes);
      stream_.next_out = reinterpret_cast<Bytef*>(dst + done);
      stream_.avail_out = uInt(want);
      const int status = ended_ ? Z_STREAM_END : inflate(&stream_, Z_NO_FLUSH);
      const size_t got = want - stream_.avail_out;
      done += got;
      produced_ += got;
      if (status == Z_STREAM_END) ended_ = true;
      if (done == n) break;
      if (status == Z_STREAM_END || (status == Z_BUF_ERROR && stream_.avail_in == 0))
        throw SerializedError(context_ + ": the data ends after " + std::to_string(produced_) +
                              " uncompressed bytes, in the " + what);
      if (status != Z_OK && status != Z_BUF_ERROR) damaged(status);
    }
  }
  uint64_t read_le(int bytes, const char* what) {
    char buf[8];
    read(buf, size_t(bytes), what);
    return load_le(buf, bytes);
  }
  uint64_t compressed_left() const { return stream_.avail_in; }

  // Reads the stream to its end, so that its checksum is checked; data
  // beyond what the counts asked for is ignored, as Mitsuba ignores it.
  void finish() {
    char scratch[4096];
    while (!ended_) {
      if (stop_request().load()) throw Interrupted("interrupted");
      stream_.next_out = reinterpret_cast<Bytef*>(scratch);
      stream_.avail_out = sizeof scratch;
      const int status = inflate(&stream_, Z_NO_FLUSH);
      if (status == Z_STREAM_END)
        ended_ = true;
      else if (status == Z_BUF_ERROR && stream_.avail_in == 0)
        throw SerializedError(context_ + ": the compressed data ends before its checksum");
      else if (status != Z_OK && status != Z_BUF_ERROR)
        damaged(status);
    }
  }

 private:
  [[noreturn]] void damaged(int status) const {
    throw SerializedError(context_ + ": the compressed data is damaged (zlib: " +
                          (stream_.msg ? stream_.msg : "error " + std::to_string(status)) + ")");
  }

  z_stream stream_{};
  const std::string& context_;
  uint64_t produced_ = 0;
  bool ended_ = false;
};

// Where mesh `index` starts: 0 for the first (as Mitsuba reads it, whether
// or not the file ends with a table), else from the table of offsets.
uint64_t mesh_offset(std::string_view bytes, uint64_t index, uint16_t version) {
  if (index == 0) return 0;
  if (bytes.size() < 8) throw SerializedError("the file is too short to hold a table of its meshes");
  const uint64_t count = load_le(bytes.data() + bytes.size() - 4, 4);
  if (index >= count)
    throw SerializedError("shape_index " + std::to_string(index) + " is out of range: the file holds " +
                          std::to_string(count) + (count == 1 ? " mesh" : " meshes"));
  const int entry = version == 4 ? 8 : 4;
  if (count * entry > bytes.size() - 4)
    throw SerializedError("its table claims " + std::to_string(count) + " meshes, more than the file can hold");
  const uint64_t table = bytes.size() - 4 - count * entry;
  const uint64_t offset = load_le(bytes.data() + table + index * entry, entry);
  if (offset > table || table - offset < 4)
    throw SerializedError("mesh " + std::to_string(index) + " is placed at byte " + std::to_string(offset) +
                          ", outside the file's " + std::to_string(table) + " bytes of meshes");
  return offset;
}

// Values stored in float or double, read as float; `finite` refuses
// values that are not finite once in float.
void read_values(Inflater& in, std::vector<float>& out, uint64_t count, bool doubles, const char* what,
                 const std::string& context, bool finite) {
  const int size = doubles ? 8 : 4;
  std::vector<char> raw(count * size);
  in.read(raw.data(), raw.size(), what);
  out.resize(count);
  for (uint64_t i = 0; i < count; ++i) {
    const uint64_t bits = load_le(raw.data() + i * size, size);
    const double v = doubles ? std::bit_cast<double>(bits) : double(std::bit_cast<float>(uint32_t(bits)));
    if (finite && !(std::abs(v) <= std::numeric_limits<float>::max()))
      throw SerializedError(context + ": vertex " + std::to_string(i / 3) + " has a " + what +
                            " value that is not finite in float");
    out[i] = float(v);
  }
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

MeshData read_serialized(std::string_view bytes, uint64_t shape_index) {
  if (bytes.size() < 4) throw SerializedError("the file is shorter than the 4-byte header of a serialized mesh");
  const auto check_header = [&](uint64_t at) {
    const uint64_t format = load_le(bytes.data() + at, 2), version = load_le(bytes.data() + at + 2, 2);
    if (format != kFormat)
      throw SerializedError("not a serialized mesh: byte " + std::to_string(at) + " starts with " + hex4(format) +
                            ", not 0x041c");
    if (version != 3 && version != 4)
      throw SerializedError("format version " + std::to_string(version) + " is not 3 or 4");
    return uint16_t(version);
  };
  const uint16_t version = check_header(0);
  const uint64_t offset = mesh_offset(bytes, shape_index, version);
  if (check_header(offset) != version)
    throw SerializedError("mesh " + std::to_string(shape_index) + " has another format version than the first");

  std::string context = "mesh " + std::to_string(shape_index);
  Inflater in(bytes.substr(offset + 4), context);
  const uint32_t flags = uint32_t(in.read_le(4, "flags"));
  if ((flags & kSinglePrecision) && (flags & kDoublePrecision))
    throw SerializedError(context + ": its flags ask for both single and double precision");
  if (version == 4) {
    std::string name;
    for (char c = 0;;) {
      in.read(&c, 1, "name");
      if (c == 0) break;
      if (name.size() == kMaxNameBytes)
        throw SerializedError(context + ": its name runs past " + std::to_string(kMaxNameBytes) + " bytes");
      name += c;
    }
    if (!name.empty()) context += " ('" + name.substr(0, 40) + (name.size() > 40 ? "...'" : "'") + ")";
  }
  const uint64_t vertices = in.read_le(8, "vertex count"), triangles = in.read_le(8, "triangle count");
  if (vertices > std::numeric_limits<uint32_t>::max())
    throw SerializedError(context + ": " + std::to_string(vertices) + " vertices are more than 2^32 - 1");

  const bool doubles = flags & kDoublePrecision;
  const uint64_t scalar = doubles ? 8 : 4;
  const uint64_t per_vertex =
      3 + ((flags & kHasNormals) ? 3 : 0) + ((flags & kHasTexcoords) ? 2 : 0) + ((flags & kHasColors) ? 3 : 0);
  const uint64_t can_hold = in.compressed_left() * kMaxExpansion + 64;
  const uint64_t vertex_bytes = vertices * per_vertex * scalar;
  if (vertex_bytes > can_hold || triangles > (can_hold - vertex_bytes) / 12)
    throw SerializedError(context + ": " + std::to_string(vertices) + " vertices and " + std::to_string(triangles) +
                          " triangles need more data than its " + std::to_string(in.compressed_left()) +
                          " compressed bytes can hold");

  MeshData mesh;
  std::vector<float> values;
  read_values(in, values, vertices * 3, doubles, "position", context, true);
  mesh.positions.resize(vertices);
  for (uint64_t v = 0; v < vertices; ++v) mesh.positions[v] = {values[3 * v], values[3 * v + 1], values[3 * v + 2]};
  if (flags & kHasNormals) {
    read_values(in, values, vertices * 3, doubles, "normal", context, false);
    mesh.face_normals = flags & kFaceNormals;
    if (!mesh.face_normals) {
      mesh.normals.resize(vertices);
      for (uint64_t v = 0; v < vertices; ++v) mesh.normals[v] = {values[3 * v], values[3 * v + 1], values[3 * v + 2]};
    }
  }
  if (flags & kHasTexcoords) {
    read_values(in, values, vertices * 2, doubles, "texture coordinate", context, false);
    mesh.uvs.resize(vertices);
    for (uint64_t v = 0; v < vertices; ++v) mesh.uvs[v] = {values[2 * v], values[2 * v + 1]};
  }
  if (flags & kHasColors) read_values(in, values, vertices * 3, doubles, "colour", context, false);

  std::vector<char> raw(triangles * 12);
  in.read(raw.data(), raw.size(), "triangles");
  mesh.indices.resize(triangles * 3);
  for (uint64_t i = 0; i < triangles * 3; ++i) {
    const uint64_t index = load_le(raw.data() + 4 * i, 4);
    if (index >= vertices)
      throw SerializedError(context + ": triangle " + std::to_string(i / 3) + " refers to vertex " +
                            std::to_string(index) + ", but the mesh has " + std::to_string(vertices) + " vertices");
    mesh.indices[i] = uint32_t(index);
  }
  in.finish();
  return mesh;
}

}  // namespace caustica
