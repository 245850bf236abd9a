#pragma once

#include <algorithm>
#include <cmath>

#include "core/math/color.h"
#include "core/math/vec.h"

namespace caustica {

struct DielectricFresnel {
  float F;       // reflectance, 1 under total internal reflection
  float cos_t;   // cosine of the refracted direction, on the far side of cos_i; 0 under TIR
  float eta_it;  // n_t / n_i along the direction of travel
  float eta_ti;  // its inverse
};

// Unpolarised Fresnel reflectance of a smooth dielectric interface. eta is
// the ratio of the inside index (below the normal) to the outside one; a
// negative cos_i means the light arrives from inside.
inline DielectricFresnel fresnel_dielectric(float cos_i, float eta) {
  const bool outside = cos_i >= 0;
  const float eta_it = outside ? eta : 1 / eta, eta_ti = outside ? 1 / eta : eta;
  const float cos_i_abs = std::abs(cos_i);
  // Snell: sin_t^2 = sin_i^2 / eta_it^2.
  const float cos_t2 = 1 - (1 - cos_i_abs * cos_i_abs) * eta_ti * eta_ti;
  if (cos_t2 <= 0) return {1, 0, eta_it, eta_ti};
  const float cos_t_abs = std::sqrt(cos_t2);
  const float rs = (cos_i_abs - eta_it * cos_t_abs) / (cos_i_abs + eta_it * cos_t_abs);
  const float rp = (eta_it * cos_i_abs - cos_t_abs) / (eta_it * cos_i_abs + cos_t_abs);
  return {0.5f * (rs * rs + rp * rp), outside ? -cos_t_abs : cos_t_abs, eta_it, eta_ti};
}

// Unpolarised Fresnel reflectance of a conductor with complex index
// eta + i k (per channel), for light arriving at cos_i > 0 from a medium of
// index 1 (eta and k given relative to it).
inline float fresnel_conductor(float cos_i, float eta, float k) {
  const float c2 = cos_i * cos_i, s2 = 1 - c2;
  const float eta2 = eta * eta, k2 = k * k;
  const float t0 = eta2 - k2 - s2;
  const float a2b2 = std::sqrt(std::max(0.0f, t0 * t0 + 4 * eta2 * k2));
  const float a = std::sqrt(std::max(0.0f, 0.5f * (a2b2 + t0)));
  const float t1 = a2b2 + c2, t2 = 2 * cos_i * a;
  const float rs = (t1 - t2) / (t1 + t2);
  const float t3 = c2 * a2b2 + s2 * s2, t4 = t2 * s2;
  const float rp = rs * (t3 - t4) / (t3 + t4);
  return 0.5f * (rs + rp);
}

inline Color fresnel_conductor(float cos_i, Color eta, Color k) {
  return {fresnel_conductor(cos_i, eta.r, k.r), fresnel_conductor(cos_i, eta.g, k.g),
          fresnel_conductor(cos_i, eta.b, k.b)};
}

// Internal diffuse reflectance of a smooth interface with relative index
// eta (inside over outside): 2 int_0^1 F(-mu) mu dmu, the cosine-weighted
// mean of the Fresnel reflectance for light arriving from inside. Below the
// critical cosine mu_c all light is reflected; above it F has a square-root
// kink at mu_c, smoothed away by mu = mu_c + (1 - mu_c) s^2 before Simpson's rule.
float internal_diffuse_reflectance(float eta);

// Mirror reflection about the normal m (wi, m and the result unit length).
inline Vec3 reflect(Vec3 w, Vec3 m) { return m * (2 * dot(w, m)) - w; }

// Refraction of w (pointing away from the surface) through a surface with
// normal m, given cos_t from fresnel_dielectric and eta_ti.
inline Vec3 refract(Vec3 w, Vec3 m, float cos_t, float eta_ti) { return m * (dot(w, m) * eta_ti + cos_t) - w * eta_ti; }

}  // namespace caustica
