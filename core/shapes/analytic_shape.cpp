#include "core/shapes/analytic_shape.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

Ray ray_from(RTCRayN* rays, unsigned n, unsigned i) {
  return {{RTCRayN_org_x(rays, n, i), RTCRayN_org_y(rays, n, i), RTCRayN_org_z(rays, n, i)},
          {RTCRayN_dir_x(rays, n, i), RTCRayN_dir_y(rays, n, i), RTCRayN_dir_z(rays, n, i)},
          RTCRayN_tfar(rays, n, i),
          RTCRayN_tnear(rays, n, i)};
}

void user_bounds(const RTCBoundsFunctionArguments* args) {
  const Bounds3 b = static_cast<const AnalyticShape*>(args->geometryUserPtr)->bounds();
  *args->bounds_o = {b.lo.x, b.lo.y, b.lo.z, 0, b.hi.x, b.hi.y, b.hi.z, 0};
}

void user_intersect(const RTCIntersectFunctionNArguments* args) {
  const auto* shape = static_cast<const AnalyticShape*>(args->geometryUserPtr);
  RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, args->N);
  RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, args->N);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    RayHit hit;
    if (!shape->intersect(ray_from(rays, args->N, i), hit)) continue;
    RTCRayN_tfar(rays, args->N, i) = hit.t;
    RTCHitN_u(hits, args->N, i) = hit.uv.x;
    RTCHitN_v(hits, args->N, i) = hit.uv.y;
    RTCHitN_Ng_x(hits, args->N, i) = 0;
    RTCHitN_Ng_y(hits, args->N, i) = 0;
    RTCHitN_Ng_z(hits, args->N, i) = 1;
    RTCHitN_primID(hits, args->N, i) = hit.prim;
    RTCHitN_geomID(hits, args->N, i) = args->geomID;
    RTCHitN_instID(hits, args->N, i, 0) = args->context->instID[0];
  }
}

void user_occluded(const RTCOccludedFunctionNArguments* args) {
  const auto* shape = static_cast<const AnalyticShape*>(args->geometryUserPtr);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    RayHit hit;
    if (shape->intersect(ray_from(args->ray, args->N, i), hit)) RTCRayN_tfar(args->ray, args->N, i) = -kInfinity;
  }
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

unsigned AnalyticShape::attach(RTCDevice device, RTCScene scene) const {
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryUserPrimitiveCount(geom, 1);
  rtcSetGeometryUserData(geom, const_cast<AnalyticShape*>(this));
  rtcSetGeometryBoundsFunction(geom, user_bounds, nullptr);
  rtcSetGeometryIntersectFunction(geom, user_intersect);
  rtcSetGeometryOccludedFunction(geom, user_occluded);
  rtcCommitGeometry(geom);
  const unsigned id = rtcAttachGeometry(scene, geom);
  rtcReleaseGeometry(geom);
  return id;
}

}  // namespace caustica
