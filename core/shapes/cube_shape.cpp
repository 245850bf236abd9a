// cube: the box [-1, 1]^3 with outward normals, before to_world.
//
//   <shape type="cube">
//       <transform name="to_world"><scale x="0.3" y="0.6" z="0.3"/></transform>
//   </shape>

#include "core/registry/properties.h"
#include "core/shapes/triangle_mesh.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

MeshData unit_cube() {
  MeshData mesh;
  // Each face gets its own four corners so its uvs and normals stay flat.
  for (int axis = 0; axis < 3; ++axis) {
    for (float side : {-1.0f, 1.0f}) {
      const int a = (axis + 1) % 3, b = (axis + 2) % 3;
      const auto base = uint32_t(mesh.positions.size());
      const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
      for (const auto& c : corners) {
        Vec3 p;
        p[axis] = side;
        p[a] = c[0];
        p[b] = c[1] * side;  // mirrors the -side face so that both wind outward
        mesh.positions.push_back(p);
        mesh.uvs.emplace_back(0.5f * (c[0] + 1), 0.5f * (c[1] + 1));
      }
      for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + i);
    }
  }
  return mesh;
}

class CubeShape final : public TriangleMesh {
 public:
  explicit CubeShape(const Properties& props) : TriangleMesh(unit_cube(), props, "cube") {}
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(CubeShape, "shape", "cube", mesh_shape_params(), {"bsdf", "emitter"});

}  // namespace caustica
