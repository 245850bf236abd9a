#include "core/shapes/mesh_crossings.h"

#include <algorithm>
#include <cmath>

#include "core/geometry/ray.h"
#include "core/shapes/triangle_mesh.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

struct Hit {
  double t;
  uint32_t prim;
  Vec2 uv;
  bool facing;  // the triangle's winding faces the line's direction
};

// Embree passes the context to the filter; the hits ride behind it.
struct CollectingContext {
  RTCIntersectContext context;
  std::vector<Hit>* hits;
  Vec3 d;
};

void collect(const RTCFilterFunctionNArguments* args) {
  auto* ctx = reinterpret_cast<CollectingContext*>(args->context);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    const Vec3 ng{RTCHitN_Ng_x(args->hit, args->N, i), RTCHitN_Ng_y(args->hit, args->N, i),
                  RTCHitN_Ng_z(args->hit, args->N, i)};
    ctx->hits->push_back({double(RTCRayN_tfar(args->ray, args->N, i)),
                          RTCHitN_primID(args->hit, args->N, i),
                          {RTCHitN_u(args->hit, args->N, i), RTCHitN_v(args->hit, args->N, i)},
                          dot(ng, ctx->d) > 0});
    args->valid[i] = 0;  // rejected, so the traversal goes on to the next
  }
}

void trace_all(RTCScene scene, Vec3 o, Vec3 d, std::vector<Hit>& hits) {
  CollectingContext ctx;
  rtcInitIntersectContext(&ctx.context);
  ctx.context.filter = collect;
  ctx.hits = &hits;
  ctx.d = d;
  RTCRayHit rh{};
  rh.ray.org_x = o.x;
  rh.ray.org_y = o.y;
  rh.ray.org_z = o.z;
  rh.ray.dir_x = d.x;
  rh.ray.dir_y = d.y;
  rh.ray.dir_z = d.z;
  rh.ray.tnear = 0;
  rh.ray.tfar = kInfinity;
  rh.ray.mask = ~0u;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene, &ctx.context, &rh);
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

MeshCrossings::MeshCrossings(RTCDevice device, const TriangleMesh& mesh) : scene_(rtcNewScene(device)) {
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
  mesh.attach(device, scene_);
  rtcCommitScene(scene_);
  const Bounds3 b = mesh.bounds();
  extent_ = length(b.hi - b.lo);
}

MeshCrossings::~MeshCrossings() { rtcReleaseScene(scene_); }

void MeshCrossings::crossings(const Ray& line, uint32_t leaf, std::vector<BoundaryCrossing>& out) const {
  std::vector<Hit> ahead, behind;
  trace_all(scene_, line.o, line.d, ahead);
  trace_all(scene_, line.o, -line.d, behind);
  // Behind the origin t is negative and the facing reversed; a hit at the
  // origin itself is kept once, ahead.
  std::vector<Hit> hits;
  hits.reserve(ahead.size() + behind.size());
  for (const Hit& h : behind)
    if (h.t > 0) hits.push_back({-h.t, h.prim, h.uv, !h.facing});
  hits.insert(hits.end(), ahead.begin(), ahead.end());
  std::sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) { return a.t < b.t; });
  // Two triangles' t for one point on their shared edge differ by their
  // rounding, a few ulps of the distances involved.
  const double reach = double(length(line.o)) + extent_;
  const double tolerance = 1e-5 * reach / double(length(line.d));
  const size_t first = out.size();
  for (size_t i = 0; i < hits.size(); ++i) {
    const Hit& h = hits[i];
    bool same = false;
    for (size_t k = out.size(); k-- > first && h.t - out[k].t <= tolerance;)
      if (out[k].entering == !h.facing) same = true;
    if (!same) out.push_back({h.t, leaf, h.prim, h.uv, !h.facing});
  }
}

}  // namespace caustica
