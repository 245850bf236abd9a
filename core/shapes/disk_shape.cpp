// disk: the unit disk in the z = 0 plane, normal +z, intersected exactly.
//
//   <shape type="disk">
//       <transform name="to_world"><scale value="0.2"/><translate y="1"/></transform>
//   </shape>

#include <cmath>

#include "core/math/constants.h"
#include "core/registry/properties.h"
#include "core/sampling/warp.h"
#include "core/shapes/analytic_shape.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class DiskShape final : public AnalyticShape {
 public:
  explicit DiskShape(const Properties& props)
      : to_world_(props.get_transform("to_world")), flip_normals_(props.get_bool("flip_normals")) {
    const float a = length(cross(to_world_.vector({1, 0, 0}), to_world_.vector({0, 1, 0})));
    if (!(a > 0)) throw props.error("to_world", "maps the disk to a line or a point");
    area_ = kPi * a;
    normal_ = normalize(to_world_.normal({0, 0, 1}));
    if (flip_normals_) normal_ = -normal_;
  }

  bool intersect(const Ray& ray, RayHit& hit) const override {
    // In object space, where the disk is z = 0 and r <= 1; an affine map
    // keeps the ray parameter t unchanged. Double precision keeps the sign of
    // a leaving ray's (offset) origin, so it never re-hits the disk at t ~ 0.
    const auto& m = to_world_.inverse_matrix().m;
    double o[3], d[3];
    for (int i = 0; i < 3; ++i) {
      o[i] = double(m[i][0]) * ray.o.x + double(m[i][1]) * ray.o.y + double(m[i][2]) * ray.o.z + m[i][3];
      d[i] = double(m[i][0]) * ray.d.x + double(m[i][1]) * ray.d.y + double(m[i][2]) * ray.d.z;
    }
    if (d[2] == 0) return false;
    const double t = -o[2] / d[2];
    if (!(t > ray.t_min) || t >= ray.t_max) return false;
    const double x = o[0] + t * d[0], y = o[1] + t * d[1];
    if (x * x + y * y > 1) return false;
    hit.t = float(t);
    hit.prim = 0;
    hit.uv = {float(x), float(y)};
    return true;
  }

  SurfaceInteraction interaction(const Ray&, const RayHit& hit) const override { return at_local(hit.uv, hit.t); }

  float area() const override { return area_; }

  Bounds3 bounds() const override {
    Bounds3 b;
    for (float x : {-1.0f, 1.0f})
      for (float y : {-1.0f, 1.0f}) {
        const Vec3 p = to_world_.point({x, y, 0}), e = to_world_.point_error({x, y, 0}) * 2;
        b.expand(p - e);
        b.expand(p + e);
      }
    return b;
  }

  PositionSample sample_position(Vec2 u) const override {
    const SurfaceInteraction si = at_local(square_to_uniform_disk_concentric(u), kInfinity);
    return {si.p, si.p_error, si.ng, si.uv, 1 / area_};
  }

  std::string kind() const override { return "disk"; }
  // Mitsuba 3's rule for disks: 1 - r, the distance to the rim in radii.
  float boundary_test(const SurfaceInteraction& si, Vec3) const override { return std::abs(1 - si.uv.x); }
  std::optional<Vec3> flat_normal() const override { return normal_; }

 private:
  SurfaceInteraction at_local(Vec2 xy, float t) const {
    SurfaceInteraction si;
    const Vec3 local{xy.x, xy.y, 0};
    si.p = to_world_.point(local);
    si.p_error = to_world_.point_error(local);
    si.t = t;
    si.shape = this;
    si.ng = normal_;
    const float r = std::sqrt(xy.x * xy.x + xy.y * xy.y), phi = azimuth(xy.x, xy.y);
    si.uv = {r, phi * kInv2Pi};
    // u = r, v = phi / 2 pi.
    si.dpdu = to_world_.vector({std::cos(phi), std::sin(phi), 0});
    si.dpdv = to_world_.vector({-std::sin(phi), std::cos(phi), 0}) * (2 * kPi * r);
    si.shading = Frame::from_normal_and_tangent(normal_, si.dpdu);
    return si;
  }

  Transform to_world_;
  bool flip_normals_;
  Vec3 normal_;
  float area_ = 0;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(DiskShape, "shape", "disk",
                         {{"to_world", ParamType::Transform, "",
                           "object-to-world transform, any affine map (an ellipse under non-uniform scale)"},
                          {"flip_normals", ParamType::Boolean, "false", "turn the surface inside out"}},
                         {"bsdf", "emitter"});

}  // namespace caustica
