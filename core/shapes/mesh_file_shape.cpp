// obj, ply, serialized: triangle meshes read from a file (OBJ through
// tinyobjloader; PLY by caustica's own reader, as Assimp, Debian's PLY
// library, crashes and hangs on damaged files; Mitsuba's serialized
// format through zlib).
//
// Polygons are triangulated. A mesh without vertex normals gets smooth
// ones, as Mitsuba gives it; face_normals (or a serialized mesh's own flag)
// shades it flat instead.
//
//   <shape type="obj">
//       <string name="filename" value="meshes/bunny.obj"/>
//   </shape>
//   <shape type="serialized">
//       <string name="filename" value="meshes/scene.serialized"/>
//       <integer name="shape_index" value="2"/>
//   </shape>

#include <filesystem>
#include <string>

#include "core/errors/interrupted.h"
#include "core/registry/properties.h"
#include "core/shapes/obj_reader.h"
#include "core/shapes/ply_reader.h"
#include "core/shapes/serialized_reader.h"
#include "core/shapes/shape_file.h"
#include "core/shapes/triangle_mesh.h"
#include "core/shapes/vertex_normals.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

MeshData flipped_tex_coords(MeshData mesh, bool flip) {
  if (flip)
    for (Vec2& uv : mesh.uvs) uv.y = 1 - uv.y;
  return mesh;
}

MeshData read_obj_file(const Properties& props, bool flip_tex_coords) {
  return flipped_tex_coords(read_shape_file(props, "mesh", [](const std::string& text) { return read_obj(text); }),
                            flip_tex_coords);
}

MeshData read_ply_file(const Properties& props, bool flip_tex_coords) {
  return flipped_tex_coords(read_shape_file(props, "mesh", [](std::string_view bytes) { return read_ply(bytes); }),
                            flip_tex_coords);
}

MeshData read_serialized_file(const Properties& props) {
  const int64_t index = props.get_int("shape_index");
  if (index < 0) throw props.error("shape_index", "must not be negative");
  return read_shape_file(props, "mesh",
                         [&](std::string_view bytes) { return read_serialized(bytes, uint64_t(index)); });
}

// What every mesh file gives the shape: triangles, and the normals it is
// shaded with.
MeshData shaded(MeshData mesh, const Properties& props) {
  if (mesh.indices.empty())
    throw props.error("filename", "mesh file '" + props.get_path("filename").string() + "' holds no triangles");
  if (props.get_bool("face_normals") || mesh.face_normals)
    mesh.normals.clear();
  else if (mesh.normals.empty())
    mesh.normals = smooth_vertex_normals(mesh);
  return mesh;
}

std::vector<ParamSpec> file_params() {
  auto params = mesh_shape_params();
  params.push_back({"filename", ParamType::String, std::nullopt, "mesh file, relative to the scene file"});
  params.push_back({"face_normals", ParamType::Boolean, "false",
                    "shade with face normals: ignore the file's vertex normals, and compute none"});
  return params;
}

std::vector<ParamSpec> file_params(const char* flip_default) {
  auto params = file_params();
  params.push_back({"flip_tex_coords", ParamType::Boolean, flip_default, "flip v to 1 - v, as Mitsuba does for OBJ"});
  return params;
}

std::vector<ParamSpec> serialized_params() {
  auto params = file_params();
  params.push_back({"shape_index", ParamType::Integer, "0", "which of the file's meshes, counted from 0"});
  return params;
}

class ObjShape final : public TriangleMesh {
 public:
  explicit ObjShape(const Properties& props)
      : TriangleMesh(shaded(read_obj_file(props, props.get_bool("flip_tex_coords")), props), props, "obj") {}
};

class PlyShape final : public TriangleMesh {
 public:
  explicit PlyShape(const Properties& props)
      : TriangleMesh(shaded(read_ply_file(props, props.get_bool("flip_tex_coords")), props), props, "ply") {}
};

class SerializedShape final : public TriangleMesh {
 public:
  explicit SerializedShape(const Properties& props)
      : TriangleMesh(shaded(read_serialized_file(props), props), props, "serialized") {}
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(ObjShape, "shape", "obj", file_params("true"), {"bsdf", "emitter"});
CAUSTICA_REGISTER_PLUGIN(PlyShape, "shape", "ply", file_params("false"), {"bsdf", "emitter"});
CAUSTICA_REGISTER_PLUGIN(SerializedShape, "shape", "serialized", serialized_params(), {"bsdf", "emitter"});

}  // namespace caustica
