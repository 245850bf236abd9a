#include "core/shapes/shape.h"

#include <cmath>
#include <stdexcept>

#include "core/bsdf/bsdf.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

// Area density to solid angle density at ref: dA = d^2 / |cos| d(omega).
float area_to_solid_angle(float pdf_area, Vec3 ref, Vec3 p, Vec3 n) {
  const Vec3 d = p - ref;
  const float dist2 = squared_length(d);
  const float cos_surface = std::abs(dot(d, n)) / std::sqrt(dist2);
  return dist2 > 0 && cos_surface > 0 ? pdf_area * dist2 / cos_surface : 0;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

uint32_t Shape::lobes() const { return bsdf_->lobes(); }

float Shape::boundary_test(const SurfaceInteraction& si, Vec3 d) const {
  if (si.shape && si.shape != this) return si.shape->boundary_test(si, d);
  return std::abs(dot(si.shading.n, -d));
}

float Shape::boundary_test_in(const Shape& shape, const SurfaceInteraction& si, Vec3 d, const Transform& to_local) {
  SurfaceInteraction local = si;
  local.p = to_local.point(si.p);
  local.shading = Frame::from_normal(normalize(to_local.normal(si.shading.n)));
  return shape.boundary_test(local, normalize(to_local.vector(d)));
}

void Shape::line_crossings(const Ray&, std::vector<BoundaryCrossing>&) const {
  throw std::logic_error(kind() + " bounds no solid a line could cross");
}

bool Shape::is_null() const { return lobes() == kNull; }

PositionSample Shape::sample_seen_from(Vec3 ref, Vec2 u) const {
  PositionSample ps = sample_position(u);
  ps.pdf = area_to_solid_angle(ps.pdf, ref, ps.p, ps.n);
  return ps;
}

float Shape::pdf_seen_from(Vec3 ref, const SurfaceInteraction& on_surface) const {
  return area_to_solid_angle(1 / area(), ref, on_surface.p, on_surface.ng);
}

}  // namespace caustica
