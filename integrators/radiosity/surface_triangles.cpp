#include "integrators/radiosity/surface_triangles.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/bsdf/bsdf.h"
#include "core/scene/scene.h"
#include "core/shapes/triangle_mesh.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

const char* const kOtherIntegrators = "path, bdpt, vcm or sppm";

std::string shape_name(const Scene& scene, const Shape& shape) {
  for (size_t i = 0; i < scene.shapes().size(); ++i)
    if (scene.shapes()[i].get() == &shape) return "shape " + std::to_string(i + 1) + " ('" + shape.kind() + "')";
  return "a '" + shape.kind() + "' shape";
}

void add_if_flat(std::vector<SurfaceTriangle>& out, SurfaceTriangle t, Vec3 front) {
  const Vec3 c = cross(t.p[1] - t.p[0], t.p[2] - t.p[0]);
  const float twice_area = length(c);
  if (!(twice_area > 0) || !std::isfinite(twice_area)) return;
  t.n = c / twice_area;
  if (dot(t.n, front) < 0) t.n = -t.n;
  out.push_back(t);
}

void add_mesh(std::vector<SurfaceTriangle>& out, const TriangleMesh& mesh) {
  const Vec2 corners[3] = {{0, 0}, {1, 0}, {0, 1}};
  for (size_t prim = 0; prim < mesh.triangle_count(); ++prim) {
    SurfaceTriangle t;
    t.shape = &mesh;
    for (int k = 0; k < 3; ++k) {
      const SurfaceInteraction si = mesh.interaction(Ray{}, RayHit{0, unsigned(prim), 0, corners[k], {}});
      t.p[k] = si.p;
      t.uv[k] = si.uv;
    }
    const Vec3 front = mesh.interaction(Ray{}, RayHit{0, unsigned(prim), 0, {1 / 3.0f, 1 / 3.0f}, {}}).ng;
    add_if_flat(out, t, front);
  }
}

// The area parametrisation of sphere and disk is continuous over the unit
// square, so a grid over the square maps to a closed mesh of the surface.
void add_tessellated(std::vector<SurfaceTriangle>& out, const Shape& shape, float edge) {
  const int cells = std::clamp(int(std::ceil(2 * std::sqrt(shape.area()) / edge)), 16, 256);
  const auto at = [&](int i, int j) { return shape.sample_position({float(i) / cells, float(j) / cells}); };
  for (int i = 0; i < cells; ++i)
    for (int j = 0; j < cells; ++j) {
      const PositionSample a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      const Vec3 front = shape.sample_position({(i + 0.5f) / cells, (j + 0.5f) / cells}).n;
      add_if_flat(out, {{a.p, b.p, c.p}, {a.uv, b.uv, c.uv}, {}, &shape}, front);
      add_if_flat(out, {{a.p, c.p, d.p}, {a.uv, c.uv, d.uv}, {}, &shape}, front);
    }
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

void check_radiosity_scene(const Scene& scene) {
  const std::string what = "integrator 'radiosity' renders only diffuse surfaces lit by area emitters; ";
  const std::string instead = "; render " + scene.source() + " with " + kOtherIntegrators;
  for (const auto& emitter : scene.emitters())
    if (!emitter->is_area())
      throw std::invalid_argument(what + "the emitter '" + emitter->plugin_name() + "' is not one" + instead);
  for (const auto& shape : scene.shapes()) {
    if (shape->kind() == "csg")
      throw std::invalid_argument(what + shape_name(scene, *shape) + " is a csg solid, which it cannot mesh" + instead);
    if (shape->kind() == "linearcurve" || shape->kind() == "bsplinecurve")
      throw std::invalid_argument(what + shape_name(scene, *shape) + " is a curve, which it cannot mesh" + instead);
    if (shape->is_instance() || shape->is_group())
      throw std::invalid_argument(what + shape_name(scene, *shape) + " is an instance, which it cannot mesh yet" +
                                  instead);
    const uint32_t lobes = shape->bsdf() ? shape->bsdf()->lobes() : 0;
    if (lobes == 0 || (lobes & ~uint32_t(kDiffuseReflection)))
      throw std::invalid_argument(what + shape_name(scene, *shape) + " has the bsdf '" +
                                  (shape->bsdf() ? shape->bsdf()->plugin_name() : "none") + "', which is not diffuse" +
                                  instead);
  }
}

std::vector<SurfaceTriangle> surface_triangles(const Scene& scene, float edge) {
  std::vector<SurfaceTriangle> out;
  for (const auto& shape : scene.shapes()) {
    if (const auto* mesh = dynamic_cast<const TriangleMesh*>(shape.get()))
      add_mesh(out, *mesh);
    else
      add_tessellated(out, *shape, edge);
  }
  return out;
}

}  // namespace caustica
