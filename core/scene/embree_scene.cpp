#include "core/scene/embree_scene.h"

#include <stdexcept>
#include <string>

#include "core/shapes/rtc_scene.h"

namespace caustica {

RTCRay to_rtc(const Ray& ray) {
  RTCRay r{};
  r.org_x = ray.o.x;
  r.org_y = ray.o.y;
  r.org_z = ray.o.z;
  r.dir_x = ray.d.x;
  r.dir_y = ray.d.y;
  r.dir_z = ray.d.z;
  r.tnear = ray.t_min;
  r.tfar = ray.t_max;
  r.time = ray.time;
  r.mask = ~0u;
  r.flags = 0;
  return r;
}

EmbreeScene::EmbreeScene(const std::vector<std::shared_ptr<Shape>>& shapes) {
  device_ = rtcNewDevice(nullptr);
  if (!device_)
    throw std::runtime_error("cannot create an Embree device (error " +
                             std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
  scene_ = build_rtc_scene(device_, shapes, by_geom_id_);
  if (const RTCError error = rtcGetDeviceError(device_); error != RTC_ERROR_NONE)
    throw std::runtime_error("Embree failed to build the scene (error " + std::to_string(int(error)) + ")");
}

EmbreeScene::~EmbreeScene() {
  rtcReleaseScene(scene_);
  rtcReleaseDevice(device_);
}

std::optional<SurfaceInteraction> EmbreeScene::intersect(const Ray& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rayhit{};
  rayhit.ray = to_rtc(ray);
  rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context, &rayhit);
  if (rayhit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  const RayHit hit{rayhit.ray.tfar,
                   rayhit.hit.primID,
                   rayhit.hit.geomID,
                   {rayhit.hit.u, rayhit.hit.v},
                   {rayhit.hit.Ng_x, rayhit.hit.Ng_y, rayhit.hit.Ng_z}};
  // Within an instance, geomID names the geometry in its group.
  const unsigned top = rayhit.hit.instID[0] != RTC_INVALID_GEOMETRY_ID ? rayhit.hit.instID[0] : rayhit.hit.geomID;
  SurfaceInteraction si = by_geom_id_[top]->interaction(ray, hit);
  si.time = ray.time;
  si.prim = hit.prim;
  si.shape_index = top;
  return si;
}

bool EmbreeScene::occluded(const Ray& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay r = to_rtc(ray);
  rtcOccluded1(scene_, &context, &r);
  return r.tfar < 0;
}

}  // namespace caustica
