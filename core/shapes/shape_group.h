#pragma once

#include <embree3/rtcore.h>

#include <memory>
#include <utility>
#include <vector>

#include "core/shapes/shape.h"

namespace caustica {

class Properties;

// shapegroup: shapes kept in their own space, not rendered themselves but
// placed any number of times by `instance` shapes that refer to the group.
// Embree builds the group's acceleration structure once and every instance
// shares it, so a thousand instances of a large mesh cost about one mesh.
//
//   <shape type="shapegroup" id="tree">
//       <shape type="ply"><string name="filename" value="tree.ply"/></shape>
//   </shape>
//   <shape type="instance">
//       <ref id="tree"/>
//       <transform name="to_world"><translate x="5"/></transform>
//   </shape>
class ShapeGroup final : public Shape {
 public:
  explicit ShapeGroup(const Properties& props);
  ~ShapeGroup() override;
  ShapeGroup(const ShapeGroup&) = delete;
  ShapeGroup& operator=(const ShapeGroup&) = delete;

  bool is_group() const override { return true; }
  // The group's Embree scene on `device`, built at the first call.
  RTCScene rtc_scene(RTCDevice device) const;
  const Shape& shape(unsigned geom_id) const { return *by_geom_id_.at(geom_id); }

  // A group is placed only through instances: these are never called.
  unsigned attach(RTCDevice, RTCScene) const override;
  SurfaceInteraction interaction(const Ray&, const RayHit&) const override;
  float area() const override { return area_; }
  Bounds3 bounds() const override { return bounds_; }
  // By area over the group's shapes, in the group's space.
  PositionSample sample_position(Vec2 u) const override;
  uint32_t lobes() const override;
  std::string kind() const override { return "shapegroup"; }

 private:
  std::vector<std::shared_ptr<Shape>> shapes_;
  float area_ = 0;
  Bounds3 bounds_;
  mutable std::vector<std::pair<RTCDevice, RTCScene>> built_;
  mutable std::vector<const Shape*> by_geom_id_;
};

}  // namespace caustica
