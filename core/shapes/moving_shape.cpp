#include "core/shapes/moving_shape.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/math/constants.h"
#include "core/shapes/rtc_scene.h"

namespace caustica {

MovingShape::MovingShape(std::shared_ptr<Shape> local, const std::vector<Transform>& keys)
    : local_(std::move(local)), motion_(keys) {}

MovingShape::~MovingShape() {
  for (const auto& [device, scene] : built_) rtcReleaseScene(scene);
}

unsigned MovingShape::attach(RTCDevice device, RTCScene scene) const {
  // A moving instance moves its group's scene, whose hits it describes
  // itself (with its own placement, the identity); another shape is placed
  // alone in a scene of its own.
  RTCScene own = local_->instanced_scene(device);
  for (const auto& [d, s] : built_)
    if (d == device) own = s;
  if (!own) {
    own = build_rtc_scene(device, {local_}, by_geom_id_);
    built_.emplace_back(device, own);
  }
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
  rtcSetGeometryInstancedScene(geom, own);
  const auto& parts = motion_.parts();
  rtcSetGeometryTimeStepCount(geom, unsigned(parts.size()));
  for (size_t k = 0; k < parts.size(); ++k) {
    const TransformParts& p = parts[k];
    RTCQuaternionDecomposition d;
    rtcInitQuaternionDecomposition(&d);
    rtcQuaternionDecompositionSetScale(&d, float(p.s[0][0]), float(p.s[1][1]), float(p.s[2][2]));
    rtcQuaternionDecompositionSetSkew(&d, float(p.s[0][1]), float(p.s[0][2]), float(p.s[1][2]));
    rtcQuaternionDecompositionSetQuaternion(&d, float(p.q[0]), float(p.q[1]), float(p.q[2]), float(p.q[3]));
    rtcQuaternionDecompositionSetTranslation(&d, float(p.t[0]), float(p.t[1]), float(p.t[2]));
    rtcSetGeometryTransformQuaternion(geom, unsigned(k), &d);
  }
  rtcCommitGeometry(geom);
  const unsigned id = rtcAttachGeometry(scene, geom);
  rtcReleaseGeometry(geom);
  return id;
}

// The hit described by the shape in its own space and moved where it is at
// the ray's time. Embree placed the ray with float copies of the
// interpolated parts; the error bound grows by that rounding, relative to
// the point's distance from the origin and the translation.
SurfaceInteraction MovingShape::interaction(const Ray& ray, const RayHit& hit) const {
  const Transform to_world = motion_.at(ray.time), to_local = to_world.inverse();
  const Ray local{to_local.point(ray.o), to_local.vector(ray.d), ray.t_max, ray.t_min, ray.time};
  SurfaceInteraction si = local_->interaction(local, hit);
  const Vec3 p_local = si.p;
  si.p = to_world.point(p_local);
  const Matrix4& m = to_world.matrix();
  double translation = 0;
  for (int i = 0; i < 3; ++i) translation = std::max(translation, std::abs(m.m[i][3]));
  Vec3 e = to_world.point_error(p_local);
  const float rounding = float(gamma(16) * (double(max_component(abs(si.p))) + translation));
  for (int i = 0; i < 3; ++i)
    e[i] += float((std::abs(m.m[i][0]) * si.p_error.x + std::abs(m.m[i][1]) * si.p_error.y +
                   std::abs(m.m[i][2]) * si.p_error.z) *
                  (1 + gamma(3))) +
            rounding;
  si.p_error = e;
  si.ng = normalize(to_world.normal(si.ng));
  si.dpdu = to_world.vector(si.dpdu);
  si.dpdv = to_world.vector(si.dpdv);
  si.shading = Frame::from_normal_and_tangent(normalize(to_world.normal(si.shading.n)), to_world.vector(si.shading.s));
  return si;
}

// The local bounds' corners placed at 65 times over the shutter, widened by
// a twentieth of the diagonal: more than a corner's arc bulges between two
// samples, for rotations of up to half a turn between a dozen keys.
Bounds3 MovingShape::bounds() const {
  const Bounds3 local = local_->bounds();
  Bounds3 b;
  constexpr int kSamples = 64;
  for (int k = 0; k <= kSamples; ++k) {
    const Transform t = motion_.at(double(k) / kSamples);
    for (int corner = 0; corner < 8; ++corner) {
      const Vec3 p{corner & 1 ? local.hi.x : local.lo.x, corner & 2 ? local.hi.y : local.lo.y,
                   corner & 4 ? local.hi.z : local.lo.z};
      b.expand(t.point(p));
    }
  }
  const Vec3 diagonal = b.hi - b.lo;
  const float margin = 0.05f * length(diagonal);
  b.expand(b.lo - Vec3(margin, margin, margin));
  b.expand(b.hi + Vec3(margin, margin, margin));
  return b;
}

// A moving shape's area light samples its still shape (MovingEmitter
// carries the samples), never the moving one.
PositionSample MovingShape::sample_position(Vec2) const { throw std::logic_error("a moving shape carries no emitter"); }

float MovingShape::boundary_test(const SurfaceInteraction& si, Vec3 d) const {
  return boundary_test_in(*local_, si, d, motion_.at(si.time).inverse());
}

}  // namespace caustica
