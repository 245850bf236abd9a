#pragma once

#include <optional>

#include "core/bsdf/surface_bsdf.h"
#include "core/geometry/interaction.h"
#include "core/math/color.h"

namespace caustica {

class Emitter;
class Medium;

// A vertex of a camera or light subpath, as the bidirectional estimators
// keep them. Densities are per unit area, except at an environment vertex
// (a direction, not a point), where they are per unit solid angle.
// A scattering event in a medium (Kind::Medium) has a position only.
struct PathVertex {
  enum class Kind : uint8_t { Camera, Light, Surface, Medium };
  Kind kind = Kind::Surface;
  // Position and frames. The camera and point lights have no normal (ng is
  // zero); an environment vertex has no position at all.
  SurfaceInteraction si;
  // For light vertices the emitter; for surface vertices the emitter of the
  // shape that was hit, if it emits.
  const Emitter* emitter = nullptr;
  bool environment = false;
  Vec3 w_env;                // environment vertices: unit direction from the scene toward the environment
  bool delta = false;        // the subpath left this vertex through a delta lobe
  bool delta_light = false;  // a delta light's vertex (point, spot, directional): no ray can hit it
  Color beta;                // the subpath's throughput up to this vertex
  float pdf_fwd = 0;         // density of this vertex as its own subpath sampled it
  float pdf_rev = 0;         // density of this vertex as the other subpath would sample it
  // For a vertex of a specular chain (see specular()), the cosine at the
  // chain's far end, the first vertex past it that is not specular, walking
  // on along its subpath (forward) or back toward its start (backward):
  // negative where the chain runs past the subpath's end.
  float chain_cos_fwd = -1, chain_cos_bwd = -1;
  // The multiple importance sampling weights' partial sum at this vertex
  // v_n (sum_partial_ratios): over the strategies in which the other
  // subpath makes v_m .. v_n (connecting v_{m-1} to v_m, or merging at
  // v_m), of h(prod_{l=m..n} pdf_rev_l / pdf_fwd_l). A strategy's weight
  // needs the densities near its connection afresh and this sum for the
  // rest, so that it costs the same for a long path as for a short one.
  // In double: a path's densities span more than float's range.
  double mis_partial = 0;
  std::optional<SurfaceBsdf> bsdf;
  // The medium the subpath reached this vertex through (for a medium
  // vertex, the one it lies in; for the camera and a light, the one they
  // sit in); null for vacuum.
  const Medium* medium = nullptr;

  Vec3 p() const { return si.p; }
  bool has_normal() const { return si.ng != Vec3(); }
  bool is_surface() const { return kind == Kind::Surface; }
  bool in_medium() const { return kind == Kind::Medium; }
};

// Whether a connection can join `v`: a point in a medium always can, a
// surface when its BSDF has a lobe that is not delta.
bool joinable(const PathVertex& v);

// Whether `v` belongs to a specular chain: a surface vertex the subpath
// left through a delta lobe that no connection can join and that emits
// nothing. Such a vertex passes its path on deterministically, whichever
// side sampled it.
bool specular(const PathVertex& v);

// How much of what arrives at the scattering vertex `v` from w_next leaves
// toward w_prev: the phase function in a medium, at a surface the BSDF
// times |cos| at w_next (both directions unit, away from v).
Color scattering(const PathVertex& v, Vec3 w_prev, Vec3 w_next);

// scattering(v, w_prev, w_next) with the solid-angle densities of sampling
// w_next from w_prev (forward) and w_prev from w_next (backward), for a
// connection's endpoint, whose value and weight need all three.
struct ScatteringBothWays {
  Color f;
  float forward = 0, backward = 0;
};
ScatteringBothWays scattering_both_ways(const PathVertex& v, Vec3 w_prev, Vec3 w_next);

// The medium a ray leaving `v` along w travels through first.
const Medium* medium_toward(const PathVertex& v, Vec3 w);

// Unit direction from vertex a toward vertex b.
inline Vec3 direction_to(const PathVertex& a, const PathVertex& b) {
  if (b.environment) return b.w_env;
  if (a.environment) return -a.w_env;
  return normalize(b.p() - a.p());
}

}  // namespace caustica
