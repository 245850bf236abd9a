#include "core/shapes/obj_reader.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <string_view>
#include <unordered_map>

#include "core/errors/interrupted.h"
#include "core/sampling/pcg32.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

// The line of the file's face number `face`, counted from 0 over the `f`
// lines of three corners or more (the reader drops the others), for error
// messages.
size_t line_of_face(const std::string& text, size_t face) {
  size_t line = 1, faces = 0;
  for (size_t begin = 0; begin < text.size(); ++line) {
    const size_t end = std::min(text.find('\n', begin), text.size());
    const std::string_view content = std::string_view(text).substr(begin, end - begin);
    const size_t at = content.find_first_not_of(" \t");
    if (at != std::string_view::npos && content[at] == 'f' && at + 1 < content.size() &&
        (content[at + 1] == ' ' || content[at + 1] == '\t')) {
      int corners = 0;
      for (size_t i = at + 1; i < content.size(); ++i)
        corners += content[i] != ' ' && content[i] != '\t' && content[i] != '\r' &&
                   (content[i - 1] == ' ' || content[i - 1] == '\t');
      if (corners >= 3 && faces++ == face) return line;
    }
    begin = end + 1;
  }
  return line;
}

struct Corner {
  int v, vt, vn;
  bool operator==(const Corner&) const = default;
};

struct CornerHash {
  size_t operator()(const Corner& c) const {
    return size_t(mix_bits((uint64_t(uint32_t(c.v)) << 32 | uint32_t(c.vt)) ^ mix_bits(uint32_t(c.vn))));
  }
};

// Checks one corner's indices (0-based, -1 where the corner has none)
// against the counts the file defines.
void check_corner(const tinyobj::index_t& index, size_t positions, size_t uvs, size_t normals, const std::string& text,
                  size_t face) {
  const auto check = [&](const char* what, int i, size_t count, bool optional) {
    if ((optional && i == -1) || (i >= 0 && size_t(i) < count)) return;
    throw ObjError("line " + std::to_string(line_of_face(text, face)) + ": face refers to " + what + " " +
                   std::to_string(int64_t(i) + 1) + " (counting from 1), but the file defines " +
                   std::to_string(count));
  };
  check("vertex", index.vertex_index, positions, false);
  check("texture coordinate", index.texcoord_index, uvs, true);
  check("normal", index.normal_index, normals, true);
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

MeshData read_obj(const std::string& text) {
  tinyobj::ObjReaderConfig config;
  config.triangulate = false;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromString(text, "", config)) {
    const std::string& error = reader.Error();
    throw ObjError(error.substr(0, error.find('\n')));
  }
  if (stop_request().load()) throw Interrupted("interrupted");
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  const size_t positions = attrib.vertices.size() / 3, uvs = attrib.texcoords.size() / 2,
               normals = attrib.normals.size() / 3;

  MeshData mesh;
  bool every_uv = uvs > 0, every_normal = normals > 0;
  std::vector<Corner> corner_of_vertex;
  const auto add_vertex = [&](const Corner& c) {
    const float* p = &attrib.vertices[3 * size_t(c.v)];
    mesh.positions.emplace_back(p[0], p[1], p[2]);
    corner_of_vertex.push_back(c);
    every_uv = every_uv && c.vt >= 0;
    every_normal = every_normal && c.vn >= 0;
    if (every_uv) mesh.uvs.emplace_back(attrib.texcoords[2 * size_t(c.vt)], attrib.texcoords[2 * size_t(c.vt) + 1]);
    if (every_normal) {
      const float* n = &attrib.normals[3 * size_t(c.vn)];
      mesh.normals.emplace_back(n[0], n[1], n[2]);
    }
    return uint32_t(mesh.positions.size() - 1);
  };
  // Most positions come with one texture/normal pair throughout: the first
  // vertex made from each position is found by index, and only positions
  // met with several pairs (hard edges, uv seams) go through a hash map.
  constexpr uint32_t kNone = ~0u;
  std::vector<uint32_t> first_of_position(positions, kNone);
  std::unordered_map<Corner, uint32_t, CornerHash> other_vertices;
  const auto vertex = [&](const tinyobj::index_t& index) {
    const Corner corner{index.vertex_index, index.texcoord_index, index.normal_index};
    uint32_t& first = first_of_position[size_t(corner.v)];
    if (first == kNone) return first = add_vertex(corner);
    if (corner_of_vertex[first] == corner) return first;
    const auto [it, fresh] = other_vertices.try_emplace(corner, 0);
    if (fresh) it->second = add_vertex(corner);
    return it->second;
  };
  std::vector<uint32_t> face_vertices;
  size_t face = 0;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    const std::vector<tinyobj::index_t>& corners = shape.mesh.indices;
    size_t first = 0;
    for (const unsigned count : shape.mesh.num_face_vertices) {
      if (face % 4096 == 0 && stop_request().load()) throw Interrupted("interrupted");
      // Faces of fewer than three corners enclose no area.
      if (count >= 3) {
        face_vertices.clear();
        for (size_t k = 0; k < count; ++k) {
          check_corner(corners[first + k], positions, uvs, normals, text, face);
          face_vertices.push_back(vertex(corners[first + k]));
        }
        for (size_t k = 1; k + 1 < count; ++k)
          mesh.indices.insert(mesh.indices.end(), {face_vertices[0], face_vertices[k], face_vertices[k + 1]});
        ++face;
      }
      first += count;
    }
  }
  // Attributes only some corners carry are dropped with their memory.
  if (!every_uv) std::vector<Vec2>().swap(mesh.uvs);
  if (!every_normal) std::vector<Vec3>().swap(mesh.normals);
  return mesh;
}

}  // namespace caustica
