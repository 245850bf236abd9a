// instance: a shapegroup placed by to_world. Embree intersects the group's
// own acceleration structure with the ray moved into the group's space;
// the hit is then described there by the shape that was hit and moved back.
// See shape_group.h for an example.

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/errors/scene_error.h"
#include "core/math/transform.h"
#include "core/registry/properties.h"
#include "core/shapes/shape_group.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class InstanceShape final : public Shape {
 public:
  explicit InstanceShape(const Properties& props)
      : to_world_(props.get_transform("to_world")), to_group_(to_world_.inverse()) {
    const auto shapes = props.children<Shape>("shape");
    if (shapes.size() != 1 || !shapes[0]->is_group())
      throw SceneError(props.where(), "an instance takes exactly one shapegroup, as <ref id=\"...\"/>");
    group_ = std::static_pointer_cast<ShapeGroup>(shapes[0]);
    const Matrix4& m = to_world_.matrix();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) abs_linear_[i][j] = std::abs(m.m[i][j]);
    det_ = std::abs(m.m[0][0] * (m.m[1][1] * m.m[2][2] - m.m[1][2] * m.m[2][1]) -
                    m.m[0][1] * (m.m[1][0] * m.m[2][2] - m.m[1][2] * m.m[2][0]) +
                    m.m[0][2] * (m.m[1][0] * m.m[2][1] - m.m[1][1] * m.m[2][0]));
    // Embree moves rays into the group's space with float copies of M and
    // of its inverse: a point's place relative to the surface is then off by
    // up to about gamma(6) |M| |M^-1| (|p| + |t|) in world units.
    const Matrix4& inv = to_world_.inverse_matrix();
    double norm = 0, inv_norm = 0;
    for (int i = 0; i < 3; ++i) {
      norm = std::max(norm, std::abs(m.m[i][0]) + std::abs(m.m[i][1]) + std::abs(m.m[i][2]));
      inv_norm = std::max(inv_norm, std::abs(inv.m[i][0]) + std::abs(inv.m[i][1]) + std::abs(inv.m[i][2]));
      translation_ = std::max(translation_, std::abs(m.m[i][3]));
    }
    embree_rounding_ = gamma(6) * norm * inv_norm;
  }

  bool is_instance() const override { return true; }
  RTCScene instanced_scene(RTCDevice device) const override { return group_->rtc_scene(device); }

  unsigned attach(RTCDevice device, RTCScene scene) const override {
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(geom, group_->rtc_scene(device));
    rtcSetGeometryTimeStepCount(geom, 1);
    float xfm[12];
    const Matrix4& m = to_world_.matrix();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 4; ++j) xfm[4 * i + j] = float(m.m[i][j]);
    rtcSetGeometryTransform(geom, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, xfm);
    rtcCommitGeometry(geom);
    const unsigned id = rtcAttachGeometry(scene, geom);
    rtcReleaseGeometry(geom);
    return id;
  }

  SurfaceInteraction interaction(const Ray& ray, const RayHit& hit) const override {
    // Not normalised: t means the same along both rays.
    const Ray local{to_group_.point(ray.o), to_group_.vector(ray.d), ray.t_max, ray.t_min, ray.time};
    SurfaceInteraction si = group_->shape(hit.geom).interaction(local, hit);
    const Vec3 p_local = si.p;
    si.p = to_world_.point(p_local);
    si.p_error = transformed_error(p_local, si.p, si.p_error);
    si.ng = normalize(to_world_.normal(si.ng));
    si.dpdu = to_world_.vector(si.dpdu);
    si.dpdv = to_world_.vector(si.dpdv);
    si.shading =
        Frame::from_normal_and_tangent(normalize(to_world_.normal(si.shading.n)), to_world_.vector(si.shading.s));
    return si;
  }

  // An instance takes no nested emitter (it declares none), and only area
  // emitters ask for their shape's area.
  float area() const override { throw std::logic_error("an instance has no emitter whose power needs its area"); }

  Bounds3 bounds() const override {
    const Bounds3 g = group_->bounds();
    Bounds3 b;
    for (int corner = 0; corner < 8; ++corner) {
      const Vec3 p{corner & 1 ? g.hi.x : g.lo.x, corner & 2 ? g.hi.y : g.lo.y, corner & 4 ? g.hi.z : g.lo.z};
      const Vec3 q = to_world_.point(p), e = to_world_.point_error(p);
      b.expand(q - e);
      b.expand(q + e);
    }
    return b;
  }

  // The group's area sample moved into place; its density per unit area
  // changes by the area's scale there, |det M| |M^-T n| (Nanson's formula).
  PositionSample sample_position(Vec2 u) const override {
    PositionSample ps = group_->sample_position(u);
    if (!(ps.pdf > 0)) return ps;
    const Vec3 n = to_world_.normal(ps.n);
    const float scale = float(det_) * length(n);
    const Vec3 p_local = ps.p;
    ps.p = to_world_.point(p_local);
    ps.p_error = transformed_error(p_local, ps.p, ps.p_error);
    ps.n = normalize(n);
    ps.pdf = scale > 0 ? ps.pdf / scale : 0;
    return ps;
  }

  uint32_t lobes() const override { return group_->lobes(); }
  std::string kind() const override { return "instance"; }
  // The hit shape's own test, in the group's space (a mesh's barycentrics
  // are read there).
  float boundary_test(const SurfaceInteraction& si, Vec3 d) const override {
    return boundary_test_in(*si.shape, si, d, to_group_);
  }

 private:
  // A bound on the error of world = to_world_.point(p) when p itself is off by up
  // to `error`: the error carried through |M|, the transform's rounding, and
  // Embree's float transforms (see the constructor).
  Vec3 transformed_error(Vec3 p, Vec3 world, Vec3 error) const {
    Vec3 e = to_world_.point_error(p);
    const float embree = float(embree_rounding_ * (max_component(abs(world)) + translation_));
    for (int i = 0; i < 3; ++i)
      e[i] += float(abs_linear_[i][0] * error.x + abs_linear_[i][1] * error.y + abs_linear_[i][2] * error.z) *
                  (1 + gamma(3)) +
              embree;
    return e;
  }

  Transform to_world_, to_group_;
  std::shared_ptr<ShapeGroup> group_;
  double abs_linear_[3][3] = {};
  double det_ = 1;
  double embree_rounding_ = 0, translation_ = 0;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(InstanceShape, "shape", "instance",
                         {{"to_world", ParamType::Transform, "", "where the group's shapes are placed"}}, {"shape"});

}  // namespace caustica
