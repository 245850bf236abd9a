#include "core/shapes/obj_reader.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <string_view>
#include <unordered_map>

#include "core/errors/interrupted.h"
#include "core/sampling/pcg32.h"

namespace caustica {

namespace {

// The line of the file's face number `face`, counted from 0 over the `f`
// lines of three corners or more (the reader drops the others), for error
// messages.
size_t line_of_face(const std::string& text, size_t face) {
  size_t line = 1, faces = 0;
  for (size_t begin = 0; begin < text.size(); ++line) {
    const size_t end = std::min(text.find('\n', begin), text.size());
    const std::string_view content = std::string_view(text).substr(begin, end - begin);
    const size_t at = content.find_first_not_of(" \t");
    if (at != std::string_view::npos && content.substr(at).starts_with("f") && at + 1 < content.size() &&
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
  std::unordered_map<Corner, uint32_t, CornerHash> vertex_of;
  bool every_uv = true, every_normal = true;
  const auto vertex = [&](const tinyobj::index_t& index) {
    const Corner corner{index.vertex_index, index.texcoord_index, index.normal_index};
    const auto [it, fresh] = vertex_of.try_emplace(corner, uint32_t(mesh.positions.size()));
    if (fresh) {
      const float* p = &attrib.vertices[3 * size_t(corner.v)];
      mesh.positions.emplace_back(p[0], p[1], p[2]);
      every_uv = every_uv && corner.vt >= 0;
      every_normal = every_normal && corner.vn >= 0;
      const float* t = corner.vt >= 0 ? &attrib.texcoords[2 * size_t(corner.vt)] : nullptr;
      mesh.uvs.push_back(t ? Vec2(t[0], t[1]) : Vec2());
      const float* n = corner.vn >= 0 ? &attrib.normals[3 * size_t(corner.vn)] : nullptr;
      mesh.normals.push_back(n ? Vec3(n[0], n[1], n[2]) : Vec3());
    }
    return it->second;
  };
  size_t face = 0;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    const std::vector<tinyobj::index_t>& corners = shape.mesh.indices;
    size_t first = 0;
    for (const unsigned count : shape.mesh.num_face_vertices) {
      if (face % 4096 == 0 && stop_request().load()) throw Interrupted("interrupted");
      for (size_t k = 0; k < count; ++k) check_corner(corners[first + k], positions, uvs, normals, text, face);
      // Faces of fewer than three corners enclose no area.
      for (size_t k = 1; k + 1 < count; ++k)
        mesh.indices.insert(mesh.indices.end(),
                            {vertex(corners[first]), vertex(corners[first + k]), vertex(corners[first + k + 1])});
      first += count;
      ++face;
    }
  }
  if (!every_uv) mesh.uvs.clear();
  if (!every_normal) mesh.normals.clear();
  return mesh;
}

}  // namespace caustica
