#pragma once

#include <string>

#include "core/shapes/mesh_format_error.h"
#include "core/shapes/triangle_mesh.h"

namespace caustica {

// A Wavefront OBJ file that cannot be read; what() says where and why.
class ObjError : public MeshFormatError {
 public:
  using MeshFormatError::MeshFormatError;
};

// Reads the triangles of an OBJ file from its text (through tinyobjloader):
// every `f` of every object and group, polygons triangulated as fans, one
// vertex per distinct position/texture/normal triple, as Mitsuba reads it.
// Normals or texture coordinates some face corners lack are dropped for the
// whole mesh. Materials, lines and points are ignored. Throws ObjError for
// a line it cannot parse or an index outside what the file defines, naming
// the line; Interrupted once stop_request() is set.
MeshData read_obj(const std::string& text);

}  // namespace caustica
