// cylinder: the curved side of a round cylinder from p0 to p1, as in
// Mitsuba (no end caps), intersected exactly. As an operand of a csg shape
// it is the solid it encloses with its two flat ends, which then bound the
// solid too.
//
//   <shape type="cylinder">
//       <point name="p0" x="0" y="0" z="0"/>
//       <point name="p1" x="0" y="1" z="0"/>
//       <float name="radius" value="0.2"/>
//   </shape>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "core/math/constants.h"
#include "core/math/frame.h"
#include "core/registry/properties.h"
#include "core/shapes/analytic_shape.h"
#include "core/shapes/similarity.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// Primitive ids of a crossing: the curved side, the end at p0, the end at p1.
enum Part : uint32_t { kSide = 0, kEndAtP0 = 1, kEndAtP1 = 2 };

class CylinderShape final : public AnalyticShape {
 public:
  explicit CylinderShape(const Properties& props) : flip_normals_(props.get_bool("flip_normals")) {
    const Transform to_world = props.get_transform("to_world");
    const std::optional<float> scale = similarity_scale(to_world);
    if (!scale) throw props.error("to_world", "a cylinder's to_world may only translate, rotate and scale uniformly");
    const float radius = props.get_float("radius");
    if (!(radius > 0) || !std::isfinite(radius)) throw props.error("radius", "must be positive");
    p0_ = to_world.point(props.get_point("p0"));
    const Vec3 p1 = to_world.point(props.get_point("p1"));
    height_ = length(p1 - p0_);
    if (!(height_ > 0) || !std::isfinite(height_)) throw props.error("p1", "must differ from p0");
    radius_ = radius * *scale;
    frame_ = Frame::from_normal((p1 - p0_) / height_);
  }

  bool intersect(const Ray& ray, RayHit& hit) const override {
    double t[2];
    const int n = side_roots(ray, t);
    for (int i = 0; i < n; ++i) {
      if (!(t[i] > ray.t_min) || t[i] >= ray.t_max) continue;
      const double z = axial(ray, t[i]);
      if (z < 0 || z > height_) continue;
      hit.t = float(t[i]);
      hit.prim = kSide;
      hit.uv = {};
      return true;
    }
    return false;
  }

  bool encloses_solid() const override { return true; }

  // The solid between the ends: the side's interval within the slab
  // between the ends' planes.
  void line_crossings(const Ray& line, std::vector<BoundaryCrossing>& out) const override {
    constexpr double kAll = std::numeric_limits<double>::infinity();
    const LocalLine l = local(line);
    double side[2] = {-kAll, kAll};
    // Parallel to the axis, the line is inside the side everywhere or nowhere.
    if (side_roots(line, side) == 0 && !(l.o[0] * l.o[0] + l.o[1] * l.o[1] < double(radius_) * radius_)) return;
    double slab[2] = {-kAll, kAll};
    uint32_t slab_part[2] = {kEndAtP0, kEndAtP1};
    if (l.d[2] != 0) {
      slab[0] = -l.o[2] / l.d[2];
      slab[1] = (height_ - l.o[2]) / l.d[2];
      if (slab[0] > slab[1]) {
        std::swap(slab[0], slab[1]);
        std::swap(slab_part[0], slab_part[1]);
      }
    } else if (!(l.o[2] > 0 && l.o[2] < height_)) {
      return;
    }
    const double enter = std::max(side[0], slab[0]), leave = std::min(side[1], slab[1]);
    if (!(enter < leave)) return;
    out.push_back({enter, 0, side[0] >= slab[0] ? uint32_t(kSide) : slab_part[0], {}, true});
    out.push_back({leave, 0, side[1] <= slab[1] ? uint32_t(kSide) : slab_part[1], {}, false});
  }

  SurfaceInteraction interaction(const Ray& ray, const RayHit& hit) const override {
    const Vec3 local = frame_.to_local(ray.at(hit.t) - p0_);
    if (hit.prim == kSide) {
      // Projected back onto the side, so the error bound is independent of t.
      const float z = std::clamp(local.z, 0.0f, height_);
      return on_side(azimuth(local.x, local.y), z, hit.t);
    }
    const float z = hit.prim == kEndAtP0 ? 0 : height_;
    SurfaceInteraction si;
    si.p = p0_ + frame_.to_world({local.x, local.y, z});
    si.p_error = (abs(p0_) + abs(si.p - p0_) + Vec3(radius_, radius_, height_)) * gamma(8);
    si.t = hit.t;
    si.shape = this;
    si.ng = hit.prim == kEndAtP0 ? -frame_.n : frame_.n;
    si.uv = {0.5f + local.x / (2 * radius_), 0.5f + local.y / (2 * radius_)};
    si.dpdu = frame_.s * (2 * radius_);
    si.dpdv = frame_.t * (2 * radius_);
    si.shading = Frame::from_normal_and_tangent(si.ng, si.dpdu);
    return si;
  }

  float area() const override { return 2 * kPi * radius_ * height_; }

  Bounds3 bounds() const override {
    const Vec3 p1 = p0_ + frame_.n * height_;
    const Vec3 pad = Vec3(radius_, radius_, radius_) * (1 + 8 * gamma(3)) + (abs(p0_) + abs(p1)) * gamma(4);
    return {min(p0_, p1) - pad, max(p0_, p1) + pad};
  }

  PositionSample sample_position(Vec2 u) const override {
    const SurfaceInteraction si = on_side(2 * kPi * u.x, u.y * height_, kInfinity);
    return {si.p, si.p_error, si.ng, si.uv, 1 / area()};
  }

  std::string kind() const override { return "cylinder"; }

 private:
  // The line in the cylinder's frame (s, t along the ends, n along the
  // axis from p0), in double.
  struct LocalLine {
    double o[3], d[3];
  };
  LocalLine local(const Ray& ray) const {
    const double o[3] = {double(ray.o.x) - p0_.x, double(ray.o.y) - p0_.y, double(ray.o.z) - p0_.z};
    const Vec3 axes[3] = {frame_.s, frame_.t, frame_.n};
    LocalLine l;
    for (int i = 0; i < 3; ++i) {
      l.o[i] = o[0] * axes[i].x + o[1] * axes[i].y + o[2] * axes[i].z;
      l.d[i] = double(ray.d.x) * axes[i].x + double(ray.d.y) * axes[i].y + double(ray.d.z) * axes[i].z;
    }
    return l;
  }
  // The distance along the axis from p0 of the line's point at t.
  double axial(const Ray& ray, double t) const {
    const LocalLine l = local(ray);
    return l.o[2] + t * l.d[2];
  }

  // Where the line meets the infinite side, ascending; 0 roots where it
  // misses it or runs parallel to the axis. Solved in double across the
  // axis with the stable form of the quadratic, as the sphere's.
  int side_roots(const Ray& ray, double t[2]) const {
    const LocalLine l = local(ray);
    const double ox = l.o[0], oy = l.o[1], dx = l.d[0], dy = l.d[1];
    const double a = dx * dx + dy * dy;
    if (!(a > 0)) return 0;
    const double b = -(ox * dx + oy * dy);
    const double px = ox + b / a * dx, py = oy + b / a * dy;
    const double r = radius_;
    const double disc = a * (r * r - (px * px + py * py));
    if (disc < 0) return 0;
    const double q = b + std::copysign(std::sqrt(disc), b);
    t[0] = q / a;
    t[1] = q == 0 ? t[0] : (ox * ox + oy * oy - r * r) / q;
    if (t[0] > t[1]) std::swap(t[0], t[1]);
    return 2;
  }

  SurfaceInteraction on_side(float phi, float z, float t) const {
    const Vec3 radial = frame_.s * std::cos(phi) + frame_.t * std::sin(phi);
    SurfaceInteraction si;
    si.p = p0_ + radial * radius_ + frame_.n * z;
    si.p_error = (abs(p0_) + abs(si.p - p0_) + Vec3(radius_, radius_, radius_)) * gamma(8);
    si.t = t;
    si.shape = this;
    si.ng = flip_normals_ ? -radial : radial;
    si.uv = {phi * kInv2Pi, z / height_};
    si.dpdu = cross(frame_.n, radial) * (2 * kPi * radius_);
    si.dpdv = frame_.n * height_;
    si.shading = Frame::from_normal_and_tangent(si.ng, si.dpdu);
    return si;
  }

  bool flip_normals_;
  Vec3 p0_;
  float height_ = 1, radius_ = 1;
  Frame frame_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(CylinderShape, "shape", "cylinder",
                         {{"p0", ParamType::Point, "0, 0, 0", "centre of one end, before to_world"},
                          {"p1", ParamType::Point, "0, 0, 1", "centre of the other end, before to_world"},
                          {"radius", ParamType::Float, "1", "radius before to_world"},
                          {"to_world", ParamType::Transform, "", "translation, rotation, uniform scale"},
                          {"flip_normals", ParamType::Boolean, "false", "normals point toward the axis"}},
                         {"bsdf", "emitter"});

}  // namespace caustica
