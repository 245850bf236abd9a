#pragma once

// Mappings from the unit square [0,1)^2 to sampling domains, each paired with
// the density it produces on that domain. Directions are unit vectors around +z.

#include <algorithm>
#include <cmath>

#include "core/math/constants.h"
#include "core/math/vec.h"

namespace caustica {

// Shirley-Chiu concentric map: squares around the centre go to concentric
// rings, so the map keeps strata compact and has no fold at the centre.
inline Vec2 square_to_uniform_disk_concentric(Vec2 u) {
  const float a = 2 * u.x - 1;
  const float b = 2 * u.y - 1;
  if (a == 0 && b == 0) return {0, 0};
  float r, phi;
  if (std::abs(a) > std::abs(b)) {
    r = a;
    phi = (kPi / 4) * (b / a);
  } else {
    r = b;
    phi = (kPi / 2) - (kPi / 4) * (a / b);
  }
  return {r * std::cos(phi), r * std::sin(phi)};
}

inline float uniform_disk_pdf() { return kInvPi; }

// z is uniform in [0,1) because the area of a spherical zone is proportional
// to its height (Archimedes).
inline Vec3 square_to_uniform_hemisphere(Vec2 u) {
  const float z = u.x;
  // (1-z)(1+z) rather than 1-z^2 keeps the radius accurate near the pole.
  const float r = std::sqrt(std::max(0.0f, (1 - z) * (1 + z)));
  const float phi = 2 * kPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

inline float uniform_hemisphere_pdf() { return kInv2Pi; }

inline Vec3 square_to_uniform_sphere(Vec2 u) {
  const float z = 1 - 2 * u.x;
  // 1 - z^2 == 4 u (1 - u) exactly, which has no cancellation at either pole.
  const float r = 2 * std::sqrt(std::max(0.0f, u.x * (1 - u.x)));
  const float phi = 2 * kPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

inline float uniform_sphere_pdf() { return kInv4Pi; }

// Malley's method: a uniform point on the disk lifted onto the hemisphere
// has a density proportional to cos(theta).
inline Vec3 square_to_cosine_hemisphere(Vec2 u) {
  const Vec2 d = square_to_uniform_disk_concentric(u);
  const float z = std::sqrt(std::max(0.0f, 1 - d.x * d.x - d.y * d.y));
  return {d.x, d.y, z};
}

inline float cosine_hemisphere_pdf(float cos_theta) { return cos_theta > 0 ? cos_theta * kInvPi : 0.0f; }

// Heitz's low-distortion map ("A Low-Distortion Map Between Triangle and
// Square", 2019): each half of the square, split along its diagonal, is
// sheared onto one half of the triangle, with constant Jacobian 1/2 and no
// square root. Returns barycentrics (b0, b1); b2 = 1 - b0 - b1. The density
// over the barycentric domain is 2.
inline Vec2 square_to_uniform_triangle(Vec2 u) {
  if (u.y > u.x) {
    const float b0 = u.x / 2;
    return {b0, u.y - b0};
  }
  const float b1 = u.y / 2;
  return {u.x - b1, b1};
}

// A cone around +z whose opening is given by its versine 1 - cos(theta_max).
// Callers that know the versine more precisely than cos(theta_max) itself
// (a far-away sphere light: sin^2 / (1 + cos)) should call this directly,
// since a float cos(theta_max) cannot resolve cones below about 1e-7 sr.
inline Vec3 square_to_uniform_cone_from_versine(Vec2 u, float one_minus_cos_theta_max) {
  // The cap's area grows linearly in 1 - cos(theta), so the versine, not the
  // cosine, is the quantity to interpolate: it keeps full relative precision.
  const float one_minus_cos = u.x * one_minus_cos_theta_max;
  // sin^2 = (1 - cos)(1 + cos); forming 1 - cos^2 from a rounded cosine would
  // cancel catastrophically in a tiny cone.
  const float sin_theta = std::sqrt(std::max(0.0f, one_minus_cos * (2 - one_minus_cos)));
  const float phi = 2 * kPi * u.y;
  return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), 1 - one_minus_cos};
}

inline float uniform_cone_pdf_from_versine(float one_minus_cos_theta_max) { return kInv2Pi / one_minus_cos_theta_max; }

// For cos_theta_max in [0.5, 1] the subtraction 1 - cos_theta_max is exact
// (Sterbenz), so a tiny cone loses nothing on the way to the versine.
inline Vec3 square_to_uniform_cone(Vec2 u, float cos_theta_max) {
  return square_to_uniform_cone_from_versine(u, 1 - cos_theta_max);
}

inline float uniform_cone_pdf(float cos_theta_max) { return uniform_cone_pdf_from_versine(1 - cos_theta_max); }

}  // namespace caustica
