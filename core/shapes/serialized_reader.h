#pragma once

#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "core/shapes/mesh_format_error.h"
#include "core/shapes/triangle_mesh.h"

namespace caustica {

// A serialized file that cannot be read; what() says which mesh, where and why.
class SerializedError : public MeshFormatError {
 public:
  using MeshFormatError::MeshFormatError;
};

// Reads mesh `shape_index` of a Mitsuba .serialized file (format versions 3
// and 4: little-endian, each mesh a zlib stream after a 4-byte header, a
// table of the meshes' offsets at the end) from the file's bytes: positions,
// normals unless the mesh asks for face normals (then MeshData::face_normals
// says so), texture coordinates and triangles; vertex colours are skipped. Any input either gives a mesh whose
// indices all name a vertex or throws SerializedError: counts are checked
// against what the compressed bytes can expand to before anything is
// allocated. Throws Interrupted once stop_request() is set.
MeshData read_serialized(std::string_view bytes, uint64_t shape_index);

}  // namespace caustica
