// rectangle: the square [-1, 1]^2 in the z = 0 plane, normal +z, before to_world.
//
//   <shape type="rectangle">
//       <transform name="to_world"><scale value="0.25"/></transform>
//   </shape>

#include "core/registry/properties.h"
#include "core/shapes/triangle_mesh.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

MeshData unit_rectangle() {
  return {{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, {}, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {0, 1, 2, 0, 2, 3}};
}

class RectangleShape final : public TriangleMesh {
 public:
  explicit RectangleShape(const Properties& props) : TriangleMesh(unit_rectangle(), props, "rectangle") {}
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(RectangleShape, "shape", "rectangle", mesh_shape_params(), {"bsdf", "emitter"});

}  // namespace caustica
