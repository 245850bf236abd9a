#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

#include "core/shapes/mesh_format_error.h"
#include "core/shapes/triangle_mesh.h"

namespace caustica {

// A PLY file that cannot be read; what() says where in the file and why.
class PlyError : public MeshFormatError {
 public:
  using MeshFormatError::MeshFormatError;
};

// Reads a PLY mesh (ascii, binary_little_endian or binary_big_endian 1.0)
// from the file's bytes: vertex positions x, y, z, optional normals nx, ny,
// nz and texture coordinates (u/v, s/t, texture_u/texture_v or
// texture_s/texture_t), and faces as lists named vertex_indices or
// vertex_index, triangulated as fans. Faces of fewer than three vertices
// and every other element and property are skipped. Any input either gives
// a mesh whose indices all name a vertex or throws PlyError: every count is
// checked against the bytes that remain before anything is allocated, so
// memory stays within a small multiple of the file's size. Throws
// Interrupted once stop_request() is set.
MeshData read_ply(std::string_view bytes);

}  // namespace caustica
