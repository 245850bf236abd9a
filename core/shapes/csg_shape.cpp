#include "core/shapes/csg_shape.h"

#include <algorithm>
#include <limits>

#include "core/errors/scene_error.h"
#include "core/registry/properties.h"
#include "core/shapes/mesh_closure.h"
#include "core/shapes/mesh_crossings.h"
#include "core/shapes/triangle_mesh.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

Bounds3 overlap(const Bounds3& a, const Bounds3& b) { return {max(a.lo, b.lo), min(a.hi, b.hi)}; }

size_t primitives(const Shape& s) {
  const auto* mesh = dynamic_cast<const TriangleMesh*>(&s);
  return mesh ? std::max<size_t>(1, mesh->triangle_count()) : 1;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CsgShape::CsgShape(const Properties& props) {
  const std::string op = props.get_string("operation");
  if (!parse_csg_operation(op, operation_))
    throw props.error("operation", "must be union, intersection or difference, not '" + op + "'");
  const auto children = props.children_at<Shape>("shape");
  if (children.size() < 2)
    throw SceneError(props.where(),
                     "a csg shape needs two or more shapes inside it, not " + std::to_string(children.size()));
  if (!props.children_at<Plugin>("emitter").empty())
    throw SceneError(props.where(),
                     "a csg shape cannot emit (its boundary is not sampled by area): put the "
                     "emitter on a shape of its own");
  size_t most_primitives = 1;
  for (const auto& [shape, where] : children) {
    Operand operand{shape};
    operand.first_leaf = uint32_t(leaves_.size());
    if (shape->emitter())
      throw SceneError(where, "a csg operand cannot emit (the solid's boundary is not sampled by area)");
    if (shape->bounds_media()) throw SceneError(where, "a csg operand cannot bound a medium");
    if (const auto* csg = dynamic_cast<const CsgShape*>(shape.get())) {
      operand.csg = csg;
      leaves_.insert(leaves_.end(), csg->leaves_.begin(), csg->leaves_.end());
    } else if (const auto* mesh = dynamic_cast<const TriangleMesh*>(shape.get())) {
      const std::string problem = mesh_closure_problem(mesh->data().positions, mesh->data().indices);
      if (!problem.empty())
        throw SceneError(where,
                         "a csg operand must bound a solid, and this " + shape->kind() + " does not: " + problem);
      operand.mesh = mesh;
      leaves_.push_back(shape.get());
    } else if (shape->encloses_solid()) {
      leaves_.push_back(shape.get());
    } else {
      throw SceneError(where,
                       "a csg operand must bound a solid (a sphere, a cylinder, a cube, a closed mesh or a csg), "
                       "not a " +
                           shape->kind());
    }
    for (uint32_t l = operand.first_leaf; l < leaves_.size(); ++l)
      most_primitives = std::max(most_primitives, primitives(*leaves_[l]));
    area_ += shape->area();
    const Bounds3 b = shape->bounds();
    if (operands_.empty())
      bounds_ = b;
    else if (operation_ == CsgOperation::Union)
      bounds_.expand(b);
    else if (operation_ == CsgOperation::Intersection)
      bounds_ = overlap(bounds_, b);
    operands_.push_back(std::move(operand));
  }
  // A hit carries its leaf, the leaf's primitive and whether it enters, in
  // Embree's 32-bit primitive id.
  if (double(most_primitives) * double(leaves_.size()) * 2 > double(std::numeric_limits<uint32_t>::max()))
    throw SceneError(props.where(), "a csg shape's operands hold too many triangles between them (" +
                                        std::to_string(most_primitives) + " in one, " + std::to_string(leaves_.size()) +
                                        " operands)");
}

CsgShape::~CsgShape() = default;

void CsgShape::prepare(RTCDevice device) const {
  if (!mesh_crossings_.empty()) return;
  mesh_crossings_.resize(operands_.size());
  for (size_t i = 0; i < operands_.size(); ++i) {
    if (operands_[i].mesh) mesh_crossings_[i] = std::make_unique<MeshCrossings>(device, *operands_[i].mesh);
    if (operands_[i].csg) operands_[i].csg->prepare(device);
  }
}

unsigned CsgShape::attach(RTCDevice device, RTCScene scene) const {
  prepare(device);
  return AnalyticShape::attach(device, scene);
}

void CsgShape::crossings(const Ray& line, uint32_t first_leaf, std::vector<BoundaryCrossing>& out) const {
  std::vector<std::vector<BoundaryCrossing>> each(operands_.size());
  for (size_t i = 0; i < operands_.size(); ++i) {
    const Operand& o = operands_[i];
    const uint32_t leaf = first_leaf + o.first_leaf;
    if (o.csg) {
      o.csg->crossings(line, leaf, each[i]);
    } else if (o.mesh) {
      mesh_crossings_[i]->crossings(line, leaf, each[i]);
    } else {
      o.shape->line_crossings(line, each[i]);
      for (BoundaryCrossing& c : each[i]) c.leaf = leaf;
    }
  }
  const std::vector<BoundaryCrossing> combined = combine_crossings(operation_, each);
  out.insert(out.end(), combined.begin(), combined.end());
}

void CsgShape::line_crossings(const Ray& line, std::vector<BoundaryCrossing>& out) const { crossings(line, 0, out); }

bool CsgShape::intersect(const Ray& ray, RayHit& hit) const {
  std::vector<BoundaryCrossing> all;
  crossings(ray, 0, all);
  for (const BoundaryCrossing& c : all) {
    if (!(c.t > double(ray.t_min))) continue;
    if (!(c.t < double(ray.t_max))) return false;
    hit.t = float(c.t);
    hit.prim = ((c.prim * uint32_t(leaves_.size()) + c.leaf) << 1) | (c.entering ? 1u : 0u);
    hit.uv = c.uv;
    return true;
  }
  return false;
}

SurfaceInteraction CsgShape::interaction(const Ray& ray, const RayHit& hit) const {
  const bool entering = hit.prim & 1;
  const uint32_t packed = hit.prim >> 1, count = uint32_t(leaves_.size());
  RayHit on_leaf = hit;
  on_leaf.prim = packed / count;
  SurfaceInteraction si = leaves_[packed % count]->interaction(ray, on_leaf);
  // The solid's outside is where the ray comes from when it enters.
  if ((dot(si.ng, ray.d) < 0) != entering) {
    si.ng = -si.ng;
    si.shading = Frame(si.shading.s, -si.shading.t, -si.shading.n);
  }
  return si;
}

PositionSample CsgShape::sample_position(Vec2) const { return {}; }

uint32_t CsgShape::lobes() const {
  uint32_t lobes = 0;
  for (const Shape* leaf : leaves_) lobes |= leaf->lobes();
  return lobes;
}

CAUSTICA_REGISTER_PLUGIN(CsgShape, "shape", "csg",
                         {{"operation", ParamType::String, "union",
                           "union, intersection, or difference (the first shape less the others)"}},
                         {"shape", "emitter"});

}  // namespace caustica
