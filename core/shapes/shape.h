#pragma once

#include <embree3/rtcore.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/geometry/bounds.h"
#include "core/geometry/interaction.h"
#include "core/math/transform.h"
#include "core/registry/plugin.h"
#include "core/shapes/boundary_crossing.h"

namespace caustica {

class Bsdf;
class Emitter;
class Medium;

// A point sampled on a surface, with its density (per unit area from
// sample_position, per unit solid angle from sample_seen_from). n is the
// geometric normal: densities convert between measures with its cosine.
struct PositionSample {
  Vec3 p, p_error, n;
  Vec2 uv;
  float pdf = 0;
};

// The hit Embree reported, before the shape turns it into an interaction.
struct RayHit {
  float t = kInfinity;
  unsigned prim = 0;
  unsigned geom = 0;  // the geometry hit within an instance's group
  Vec2 uv;            // Embree's barycentrics for triangles, shape-defined otherwise
  Vec3 ng;            // Embree's geometric normal, not normalised (within an instance, in its group's space)
};

// A surface in the scene: Embree geometry plus what lights and integrators
// need of it. Shapes are in world space once constructed.
class Shape : public Plugin {
 public:
  // Adds the geometry to `scene` and returns its Embree id.
  virtual unsigned attach(RTCDevice device, RTCScene scene) const = 0;
  virtual SurfaceInteraction interaction(const Ray& ray, const RayHit& hit) const = 0;
  virtual float area() const = 0;
  virtual Bounds3 bounds() const = 0;
  virtual PositionSample sample_position(Vec2 u) const = 0;
  // A point sampled for a viewer at `ref`, its pdf converted to solid angle
  // at ref. Shapes that can sample only what ref sees (a sphere's visible
  // cone) override both; by default the area sample is converted.
  virtual PositionSample sample_seen_from(Vec3 ref, Vec2 u) const;
  virtual float pdf_seen_from(Vec3 ref, const SurfaceInteraction& on_surface) const;
  virtual std::string kind() const = 0;
  // A shapegroup, placed only through instances.
  virtual bool is_group() const { return false; }
  // An instance of a shapegroup: it cannot carry an emitter, nor sit in a group.
  virtual bool is_instance() const { return false; }
  // The Embree scene an instance places (its group's), for a moving
  // instance to place with its own motion; null for other shapes.
  virtual RTCScene instanced_scene(RTCDevice /*device*/) const { return nullptr; }
  // A shape whose place changes over the shutter interval (MovingShape).
  virtual bool moves() const { return false; }
  // The BsdfLobe flags of what the shape reflects (an instance's are its group's).
  virtual uint32_t lobes() const;
  // Shapes that bound a solid and cross a line analytically (a sphere, a
  // csg solid) say so and append every crossing of the whole line
  // o + t d, ascending in t, negative t included; csg combines them.
  // Closed meshes are solids too, crossed by csg through Embree.
  virtual bool encloses_solid() const { return false; }
  // The shapes whose materials this one's surface shows, and which hits
  // name: itself, or a csg solid's operands.
  virtual std::vector<const Shape*> material_surfaces() const { return {this}; }
  virtual void line_crossings(const Ray& line, std::vector<BoundaryCrossing>& out) const;
  // The geometric normal every point of the shape shares, where it has one
  // (a rectangle, a disk, any flat mesh): a light tree bounds an area
  // light on the shape by the half-space in front of it.
  virtual std::optional<Vec3> flat_normal() const { return std::nullopt; }
  // Why the shape cannot show `bsdf` (a curve, seen only from outside, and
  // a material that transmits); empty where it can.
  virtual std::string refused_material(const Bsdf&) const { return ""; }
  // Mitsuba 3's boundary test at `si`, met by a ray along the unit
  // direction `d`: a soft indicator, 0 at the shape's silhouette or edge
  // and positive elsewhere (the aov kind boundary_test). By default the
  // |cosine| between the shading normal and the ray (a sphere's, a
  // cylinder's, a curve's); a shape whose hits are another's (CSG) asks
  // that one.
  virtual float boundary_test(const SurfaceInteraction& si, Vec3 d) const;

 protected:
  // The boundary test of `shape`, asked in the space `to_local` maps `si`
  // and `d` into (an instance's group, a moving shape's still pose).
  static float boundary_test_in(const Shape& shape, const SurfaceInteraction& si, Vec3 d, const Transform& to_local);

 public:
  // A null surface, which scatters nothing (a medium's index-matched
  // boundary): paths and the first-hit layers look through it.
  bool is_null() const;

  const std::shared_ptr<Bsdf>& bsdf() const { return bsdf_; }
  const Emitter* emitter() const { return emitter_; }
  void set_bsdf(std::shared_ptr<Bsdf> bsdf) { bsdf_ = std::move(bsdf); }
  void set_emitter(const Emitter* e) { emitter_ = e; }

  // A shape given an interior or an exterior medium bounds media: a ray
  // crossing it enters the medium on the side it leaves toward (none is
  // vacuum). A ray crossing any other shape stays in the medium it was in.
  bool bounds_media() const { return interior_ || exterior_; }
  const Medium* interior() const { return interior_.get(); }
  const Medium* exterior() const { return exterior_.get(); }
  void set_media(std::shared_ptr<const Medium> interior, std::shared_ptr<const Medium> exterior) {
    interior_ = std::move(interior);
    exterior_ = std::move(exterior);
  }

 private:
  std::shared_ptr<Bsdf> bsdf_;
  const Emitter* emitter_ = nullptr;
  std::shared_ptr<const Medium> interior_, exterior_;
};

}  // namespace caustica
