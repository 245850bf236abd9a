// linearcurve and bsplinecurve: hair and fibres as Embree's round curves,
// read as Mitsuba reads them (core/shapes/curve_file.h). A linear curve is
// a chain of cones joined and capped by spheres; a B-spline curve a tube
// swept along the uniform cubic B-spline of its control points, one segment
// per four consecutive points, its radius interpolated alike. to_world
// moves the control points; the radii stay as written, as in Mitsuba.
//
//   <shape type="bsplinecurve">
//       <string name="filename" value="meshes/fur.txt"/>
//   </shape>
//
// A curve is a surface seen from outside: Embree does not report a ray
// leaving a tube from within, so a curve refuses materials that transmit
// light, and carries no emitter.

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "core/bsdf/bsdf.h"
#include "core/math/constants.h"
#include "core/registry/properties.h"
#include "core/sampling/discrete_distribution.h"
#include "core/shapes/curve_file.h"
#include "core/shapes/shape.h"
#include "core/shapes/shape_file.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

struct CurveBasis {
  const char* name;
  RTCGeometryType type;
  size_t span;  // control points per segment
};
constexpr CurveBasis kLinear{"linearcurve", RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE, 2};
constexpr CurveBasis kBspline{"bsplinecurve", RTC_GEOMETRY_TYPE_ROUND_BSPLINE_CURVE, 4};

class CurveShape : public Shape {
 public:
  CurveShape(const Properties& props, const CurveBasis& basis) : basis_(basis) {
    const CurveData curves =
        read_shape_file(props, "curve", [&](const std::string& text) { return read_curves(text, basis.span); });
    const Transform to_world = props.get_transform("to_world");
    points_.reserve(curves.points.size());
    for (const auto& c : curves.points) {
      const Vec3 p = to_world.point(Vec3d(c.p.x, c.p.y, c.p.z));
      points_.push_back({p.x, p.y, p.z, c.radius});
    }
    for (size_t k = 0; k < curves.first.size(); ++k) {
      const size_t end = k + 1 < curves.first.size() ? curves.first[k + 1] : curves.points.size();
      for (size_t i = curves.first[k]; i + basis.span <= end; ++i) segments_.push_back(uint32_t(i));
    }
    std::vector<float> areas;
    for (uint32_t s = 0; s < segments_.size(); ++s) areas.push_back(segment_area(s));
    for (float a : areas) area_ += a;
    if (!(area_ > 0)) throw props.error("filename", "every curve has radius 0: there is no surface to render");
    by_area_.emplace(areas);
  }

  unsigned attach(RTCDevice device, RTCScene scene) const override {
    RTCGeometry geom = rtcNewGeometry(device, basis_.type);
    rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, points_.data(), 0, sizeof(Point4),
                               points_.size());
    rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, segments_.data(), 0, sizeof(uint32_t),
                               segments_.size());
    rtcCommitGeometry(geom);
    const unsigned id = rtcAttachGeometry(scene, geom);
    rtcReleaseGeometry(geom);
    return id;
  }

  // Embree's normal is the tube's at the hit. The point is the ray's at
  // Embree's t; its error bound, 64 roundings of its coordinates and the
  // radius, covers the intersector's iterations: a ray leaving a hair 1 mm
  // thick 100 m from the origin never finds it again (curve_test.cpp).
  SurfaceInteraction interaction(const Ray& ray, const RayHit& hit) const override {
    const float v = std::clamp(hit.uv.x, 0.0f, 1.0f);
    const Point4 c = centre(hit.prim, v);
    Vec3 n = hit.ng;
    const Vec3 p = ray.at(hit.t);
    if (!(dot(n, n) > 0)) n = p - c.p();
    n = normalize(n);
    SurfaceInteraction si;
    si.t = hit.t;
    si.shape = this;
    si.p = p;
    si.ng = n;
    si.p_error = (abs(p) + Vec3(c.r, c.r, c.r)) * gamma(64);
    const Vec3 along = derivative(hit.prim, v);
    const Vec3 around = cross(n, along);
    const float circumference = 2 * kPi * c.r;
    si.dpdu = dot(around, around) > 0 ? normalize(around) * circumference : Vec3{};
    si.dpdv = along * float(segments_.size());
    si.uv = {angle_around(n, along), (float(hit.prim) + v) / float(segments_.size())};
    si.shading = Frame::from_normal_and_tangent(n, dot(along, along) > 0 ? along : si.dpdu);
    return si;
  }

  float area() const override { return area_; }

  Bounds3 bounds() const override {
    Bounds3 b;
    for (const Point4& q : points_) {
      b.expand(q.p() - Vec3(q.r, q.r, q.r));
      b.expand(q.p() + Vec3(q.r, q.r, q.r));
    }
    return b;
  }

  // A segment in proportion to its area, then a point along it uniform in
  // its parameter and around it in angle: points spread over the surface
  // (for the scene analysis), their density 1 / area only where the radius
  // and the speed along the segment are constant. Curves carry no emitter,
  // which would need the exact density.
  PositionSample sample_position(Vec2 u) const override {
    float pmf = 0, v = 0;
    const auto s = uint32_t(by_area_->sample(u.x, &pmf, &v));
    const Point4 c = centre(s, v);
    const Vec3 along = derivative(s, v);
    const Frame f = Frame::from_normal(dot(along, along) > 0 ? normalize(along) : Vec3{0, 0, 1});
    const float phi = 2 * kPi * u.y;
    const Vec3 n = f.s * std::cos(phi) + f.t * std::sin(phi);
    PositionSample ps;
    ps.p = c.p() + n * c.r;
    ps.n = n;
    ps.p_error = (abs(ps.p) + Vec3(c.r, c.r, c.r)) * gamma(64);
    ps.uv = {u.y, (float(s) + v) / float(segments_.size())};
    ps.pdf = 1 / area_;
    return ps;
  }

  std::string kind() const override { return basis_.name; }

  std::string refused_material(const Bsdf& bsdf) const override {
    if (bsdf.lobes() & kTransmission)
      return std::string("a ") + basis_.name + " cannot take a material that transmits light (" + bsdf.plugin_name() +
             "): Embree does not report a ray leaving a curve from within";
    return "";
  }

 private:
  struct Point4 {
    float x, y, z, r;
    Vec3 p() const { return {x, y, z}; }
  };

  // The centre line and radius of segment s at parameter v in [0, 1].
  Point4 centre(uint32_t s, float v) const {
    const Point4* q = &points_[segments_[s]];
    float w[4];
    const size_t n = weights(v, w);
    Point4 c{0, 0, 0, 0};
    for (size_t i = 0; i < n; ++i) {
      c.x += w[i] * q[i].x;
      c.y += w[i] * q[i].y;
      c.z += w[i] * q[i].z;
      c.r += w[i] * q[i].r;
    }
    return c;
  }

  // d(centre line)/dv.
  Vec3 derivative(uint32_t s, float v) const {
    const Point4* q = &points_[segments_[s]];
    if (basis_.span == 2) return q[1].p() - q[0].p();
    const float a = 1 - v;
    const float d[4] = {-a * a / 2, (3 * v * v - 4 * v) / 2, (-3 * v * v + 2 * v + 1) / 2, v * v / 2};
    Vec3 t;
    for (int i = 0; i < 4; ++i) t = t + q[i].p() * d[i];
    return t;
  }

  // The basis functions at v: linear, or the uniform cubic B-spline's.
  size_t weights(float v, float* w) const {
    if (basis_.span == 2) {
      w[0] = 1 - v;
      w[1] = v;
      return 2;
    }
    const float a = 1 - v, v2 = v * v, v3 = v2 * v;
    w[0] = a * a * a / 6;
    w[1] = (3 * v3 - 6 * v2 + 4) / 6;
    w[2] = (-3 * v3 + 3 * v2 + 3 * v + 1) / 6;
    w[3] = v3 / 6;
    return 4;
  }

  // The angle of n around the segment's direction, over 2 pi, from a frame
  // fixed by the direction alone.
  static float angle_around(Vec3 n, Vec3 along) {
    if (!(dot(along, along) > 0)) return 0;
    const Frame f = Frame::from_normal(normalize(along));
    float phi = std::atan2(dot(n, f.t), dot(n, f.s));
    if (phi < 0) phi += 2 * kPi;
    return phi * kInv2Pi;
  }

  // 2 pi r |c'| integrated over the segment by the midpoint rule (32 steps).
  float segment_area(uint32_t s) const {
    double a = 0;
    for (int i = 0; i < 32; ++i) {
      const float v = (float(i) + 0.5f) / 32;
      a += 2 * M_PI * centre(s, v).r * length(derivative(s, v)) / 32;
    }
    return float(a);
  }

  const CurveBasis& basis_;
  std::vector<Point4> points_;
  std::vector<uint32_t> segments_;
  float area_ = 0;
  std::optional<DiscreteDistribution> by_area_;
};

std::vector<ParamSpec> curve_params(const char* points) {
  return {{"filename", ParamType::String, std::nullopt,
           std::string("curve file, relative to the scene file: one control point per line, x y z radius, a blank "
                       "line between curves; ") +
               points},
          {"to_world", ParamType::Transform, "", "moves the control points; radii stay as written"}};
}

class LinearCurveShape final : public CurveShape {
 public:
  explicit LinearCurveShape(const Properties& props) : CurveShape(props, kLinear) {}
};

class BsplineCurveShape final : public CurveShape {
 public:
  explicit BsplineCurveShape(const Properties& props) : CurveShape(props, kBspline) {}
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(LinearCurveShape, "shape", "linearcurve",
                         curve_params("each curve at least 2 points, a cone from each to the next"), {"bsdf"});
CAUSTICA_REGISTER_PLUGIN(BsplineCurveShape, "shape", "bsplinecurve",
                         curve_params("each curve at least 4 points, a segment for every 4 in a row"), {"bsdf"});

}  // namespace caustica
