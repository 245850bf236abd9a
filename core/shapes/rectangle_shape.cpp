// rectangle: the square [-1, 1]^2 in the z = 0 plane, normal +z, before to_world.
//
//   <shape type="rectangle">
//       <transform name="to_world"><scale value="0.25"/></transform>
//   </shape>

#include <algorithm>
#include <cmath>

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

  // Mitsuba 3's rule for rectangles: the distance to the nearest edge in
  // (u, v), 1/2 at the centre.
  float boundary_test(const SurfaceInteraction& si, Vec3) const override {
    return std::min(0.5f - std::abs(si.uv.x - 0.5f), 0.5f - std::abs(si.uv.y - 0.5f));
  }
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(RectangleShape, "shape", "rectangle", mesh_shape_params(), {"bsdf", "emitter"});

}  // namespace caustica
