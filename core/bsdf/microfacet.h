#pragma once

#include <string>

#include "core/math/vec.h"

namespace caustica {

// A microfacet normal distribution in the local shading frame (normal +z),
// possibly anisotropic (alpha_u along the frame's s axis, alpha_v along t),
// with the Smith height-correlated masking-shadowing function.
class MicrofacetDistribution {
 public:
  enum class Type { Beckmann, GGX };

  MicrofacetDistribution(Type type, float alpha_u, float alpha_v);
  // "beckmann" or "ggx"; throws std::invalid_argument otherwise.
  static Type parse_type(const std::string& name);

  Type type() const { return type_; }
  float alpha_u() const { return alpha_u_; }
  float alpha_v() const { return alpha_v_; }

  // Density of microfacet normals per unit projected area: integral of D(m) cos(theta_m) = 1.
  float D(Vec3 m) const;
  // Smith's Lambda for direction w.
  float lambda(Vec3 w) const;
  // Masking of w by the microsurface, for microfacet normal m.
  float G1(Vec3 w, Vec3 m) const;
  // Height-correlated masking-shadowing of the pair.
  float G(Vec3 wo, Vec3 wi, Vec3 m) const;

  // Samples a microfacet normal seen from wi (wi.z > 0): the distribution of
  // visible normals, G1(wi, m) max(0, wi.m) D(m) / wi.z.
  Vec3 sample(Vec3 wi, Vec2 u) const;
  // The density of sample() producing m, per unit solid angle of m.
  float pdf(Vec3 wi, Vec3 m) const;

  // Samples a microfacet normal regardless of direction: D(m) cos(theta_m).
  // More of its samples are masked than sample()'s; kept for comparison and
  // for scenes asking for it (sample_visible = false).
  Vec3 sample_D(Vec2 u) const;
  // The density of sample_D() producing m, per unit solid angle of m.
  float pdf_D(Vec3 m) const;

 private:
  Type type_;
  float alpha_u_, alpha_v_;
};

}  // namespace caustica
