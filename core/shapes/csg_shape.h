#pragma once

#include <memory>
#include <vector>

#include "core/shapes/analytic_shape.h"
#include "core/shapes/csg_combine.h"

namespace caustica {

class MeshCrossings;
class Properties;
class TriangleMesh;

// csg: a solid made of two or more solids by union, intersection or
// difference (the first less all the others), each a sphere, a cylinder
// (with its ends), a closed triangle mesh (cube, obj, ply, serialized) or
// another csg, nested to any depth. A ray meets the solid where the operands' crossings of its line,
// combined, change inside to outside; the surface there is the operand's
// (its material, uv and shading), with the normal turned to the solid's
// outside, so the part of a subtracted operand that bounds a difference
// faces into that operand. Operands keep their own materials; a csg cannot
// emit, bound media, or be sampled by area.
//
//   <shape type="csg">
//       <string name="operation" value="intersection"/>
//       <shape type="sphere"><point name="center" y="-0.8"/><ref id="glass"/></shape>
//       <shape type="sphere"><point name="center" y="0.8"/><ref id="glass"/></shape>
//   </shape>
class CsgShape final : public AnalyticShape {
 public:
  explicit CsgShape(const Properties& props);
  ~CsgShape() override;
  CsgShape(const CsgShape&) = delete;
  CsgShape& operator=(const CsgShape&) = delete;

  unsigned attach(RTCDevice device, RTCScene scene) const override;
  bool intersect(const Ray& ray, RayHit& hit) const override;
  SurfaceInteraction interaction(const Ray& ray, const RayHit& hit) const override;
  // The operands' surfaces together, of which the solid's boundary is a part.
  float area() const override { return area_; }
  Bounds3 bounds() const override { return bounds_; }
  // Refused where it would be needed (an emitter, radiosity's patches):
  // never sampled.
  PositionSample sample_position(Vec2 u) const override;
  uint32_t lobes() const override;
  std::string kind() const override { return "csg"; }
  bool encloses_solid() const override { return true; }
  void line_crossings(const Ray& line, std::vector<BoundaryCrossing>& out) const override;
  std::vector<const Shape*> material_surfaces() const override { return leaves_; }

  // The shapes whose surfaces bound the solid, nested csg operands'
  // included, in order; a crossing's leaf indexes them.
  const std::vector<const Shape*>& leaves() const { return leaves_; }

 private:
  struct Operand {
    std::shared_ptr<Shape> shape;
    const CsgShape* csg = nullptr;       // a nested csg
    const TriangleMesh* mesh = nullptr;  // a closed mesh, crossed through Embree
    uint32_t first_leaf = 0;
  };
  // Builds the meshes' Embree scenes, nested ones' too, once.
  void prepare(RTCDevice device) const;
  void crossings(const Ray& line, uint32_t first_leaf, std::vector<BoundaryCrossing>& out) const;

  CsgOperation operation_;
  std::vector<Operand> operands_;
  std::vector<const Shape*> leaves_;
  float area_ = 0;
  Bounds3 bounds_;
  mutable std::vector<std::unique_ptr<MeshCrossings>> mesh_crossings_;  // per operand, null but for meshes
};

}  // namespace caustica
