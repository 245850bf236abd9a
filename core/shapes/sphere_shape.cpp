// sphere: an exact sphere, intersected analytically (not tessellated).
//
//   <shape type="sphere">
//       <point name="center" x="0" y="1" z="0"/>
//       <float name="radius" value="0.25"/>
//   </shape>

#include <cmath>
#include <optional>
#include <utility>

#include "core/math/constants.h"
#include "core/registry/properties.h"
#include "core/sampling/warp.h"
#include "core/shapes/analytic_shape.h"
#include "core/shapes/similarity.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class SphereShape final : public AnalyticShape {
 public:
  explicit SphereShape(const Properties& props) : flip_normals_(props.get_bool("flip_normals")) {
    const Transform to_world = props.get_transform("to_world");
    const float radius = props.get_float("radius");
    if (!(radius > 0)) throw props.error("radius", "must be positive");
    const std::optional<float> scale = similarity_scale(to_world);
    if (!scale) throw props.error("to_world", "a sphere's to_world may only translate, rotate and scale uniformly");
    center_ = to_world.point(props.get_point("center"));
    radius_ = radius * *scale;
  }

  bool intersect(const Ray& ray, RayHit& hit) const override {
    double t0, t1;
    if (!roots(ray, t0, t1)) return false;
    const double t = t0 > ray.t_min ? t0 : t1;
    if (!(t > ray.t_min) || t >= ray.t_max) return false;
    hit.t = float(t);
    hit.prim = 0;
    hit.uv = {};
    return true;
  }

  bool encloses_solid() const override { return true; }

  void line_crossings(const Ray& line, std::vector<BoundaryCrossing>& out) const override {
    double t0, t1;
    if (!roots(line, t0, t1)) return;
    out.push_back({t0, 0, 0, {}, true});
    out.push_back({t1, 0, 0, {}, false});
  }

  SurfaceInteraction interaction(const Ray& ray, const RayHit& hit) const override {
    // Projected back onto the sphere so the error bound is independent of t.
    const Vec3 p = ray.at(hit.t);
    return at_direction(normalize(p - center_), hit.t);
  }

  float area() const override { return 4 * kPi * radius_ * radius_; }

  Bounds3 bounds() const override {
    // Padded so Embree's float bounds test never culls an exact hit.
    const Vec3 r = Vec3(radius_, radius_, radius_) * (1 + 4 * gamma(3));
    return {center_ - r - abs(center_) * gamma(3), center_ + r + abs(center_) * gamma(3)};
  }

  PositionSample sample_position(Vec2 u) const override {
    const SurfaceInteraction si = at_direction(square_to_uniform_sphere(u), kInfinity);
    return {si.p, si.p_error, si.ng, si.uv, 1 / area()};
  }

  // Seen from outside, only the cone the sphere subtends is sampled,
  // uniformly in solid angle (each direction hits the near side once).
  PositionSample sample_seen_from(Vec3 ref, Vec2 u) const override {
    const Vec3 to_center = center_ - ref;
    const float dist2 = squared_length(to_center);
    if (dist2 <= radius_ * radius_ * (1 + 1e-4f)) return AnalyticShape::sample_seen_from(ref, u);
    const float dist = std::sqrt(dist2);
    const float sin2_max = radius_ * radius_ / dist2;
    const float cos_max = std::sqrt(std::max(0.0f, 1 - sin2_max));
    // 1 - cos from sin^2 keeps its precision for a far-away, tiny cone.
    const float versine = sin2_max / (1 + cos_max);
    const Vec3 local = square_to_uniform_cone_from_versine(u, versine);
    const Vec3 dir = Frame::from_normal(to_center / dist).to_world(local);
    // Nearer root of |ref + t dir - c| = r, with the discriminant clamped at
    // the silhouette where rounding can push it below zero.
    const float sin2 = std::max(0.0f, 1 - local.z * local.z);
    const float t = dist * local.z - std::sqrt(std::max(0.0f, radius_ * radius_ - dist2 * sin2));
    const SurfaceInteraction si = at_direction(normalize(ref + dir * t - center_), kInfinity);
    return {si.p, si.p_error, si.ng, si.uv, uniform_cone_pdf_from_versine(versine)};
  }

  float pdf_seen_from(Vec3 ref, const SurfaceInteraction& on_surface) const override {
    const float dist2 = squared_length(center_ - ref);
    if (dist2 <= radius_ * radius_ * (1 + 1e-4f)) return AnalyticShape::pdf_seen_from(ref, on_surface);
    const float sin2_max = radius_ * radius_ / dist2;
    return uniform_cone_pdf_from_versine(sin2_max / (1 + std::sqrt(std::max(0.0f, 1 - sin2_max))));
  }

  std::string kind() const override { return "sphere"; }

 private:
  SurfaceInteraction at_direction(Vec3 n, float t) const {
    SurfaceInteraction si;
    const Vec3 offset = n * radius_;
    si.p = center_ + offset;
    si.p_error = (abs(offset) + abs(center_)) * gamma(6);
    si.t = t;
    si.shape = this;
    const Vec3 normal = flip_normals_ ? -n : n;
    si.ng = normal;
    si.uv = {azimuth(n.x, n.y) * kInv2Pi, std::acos(std::clamp(n.z, -1.0f, 1.0f)) * kInvPi};
    // u = phi / 2 pi, v = theta / pi.
    const float sin_theta = std::sqrt(std::max(0.0f, n.x * n.x + n.y * n.y));
    si.dpdu = Vec3(-offset.y, offset.x, 0) * (2 * kPi);
    si.dpdv = sin_theta > 0 ? Vec3(n.z * n.x / sin_theta, n.z * n.y / sin_theta, -sin_theta) * (kPi * radius_)
                            : Vec3(kPi * radius_, 0, 0);
    si.shading = Frame::from_normal_and_tangent(normal, si.dpdu);
    return si;
  }

  // Where the line o + t d meets the sphere, t0 <= t1. Solved in double
  // around the centre, with the discriminant in the numerically stable form
  // r^2 - |oc - (oc.d) d|^2 / |d|^2, so a ray leaving the surface never
  // finds it again at t ~ 0.
  bool roots(const Ray& ray, double& t0, double& t1) const {
    const double ox = double(ray.o.x) - center_.x, oy = double(ray.o.y) - center_.y, oz = double(ray.o.z) - center_.z;
    const double dx = ray.d.x, dy = ray.d.y, dz = ray.d.z;
    const double a = dx * dx + dy * dy + dz * dz;
    const double b = -(ox * dx + oy * dy + oz * dz);  // half of -B
    const double px = ox + b / a * dx, py = oy + b / a * dy, pz = oz + b / a * dz;
    const double r = radius_;
    const double disc = a * (r * r - (px * px + py * py + pz * pz));
    if (disc < 0) return false;
    const double q = b + std::copysign(std::sqrt(disc), b);
    t0 = q / a;
    t1 = q == 0 ? t0 : ((ox * ox + oy * oy + oz * oz) - r * r) / q;
    if (t0 > t1) std::swap(t0, t1);
    return true;
  }

  bool flip_normals_;
  Vec3 center_;
  float radius_ = 1;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(SphereShape, "shape", "sphere",
                         {{"center", ParamType::Point, "0, 0, 0", "centre before to_world"},
                          {"radius", ParamType::Float, "1", "radius before to_world"},
                          {"to_world", ParamType::Transform, "", "translation, rotation, uniform scale"},
                          {"flip_normals", ParamType::Boolean, "false",
                           "normals point inward (an emitter emits inward)"}},
                         {"bsdf", "emitter"});

}  // namespace caustica
