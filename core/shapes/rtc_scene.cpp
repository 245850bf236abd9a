#include "core/shapes/rtc_scene.h"

namespace caustica {

RTCScene build_rtc_scene(RTCDevice device, const std::vector<std::shared_ptr<Shape>>& shapes,
                         std::vector<const Shape*>& by_geom_id) {
  RTCScene scene = rtcNewScene(device);
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
  by_geom_id.clear();
  for (const auto& shape : shapes) {
    const unsigned id = shape->attach(device, scene);
    if (id >= by_geom_id.size()) by_geom_id.resize(id + 1, nullptr);
    by_geom_id[id] = shape.get();
  }
  rtcCommitScene(scene);
  return scene;
}

}  // namespace caustica
