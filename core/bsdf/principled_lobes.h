#pragma once

#include <string>

#include "core/math/color.h"
#include "core/math/vec.h"

namespace caustica {

class Properties;

// The pieces of Burley's principled material ("Physically Based Shading at
// Disney", SIGGRAPH 2012 course; "Extending the Disney BRDF to a BSDF with
// Integrated Subsurface Scattering", 2015) that no other material uses.

// base / lum(base), the hue of a colour at unit luminance; white where the
// colour is black.
Color tint_of(Color base);

// A lobe's sampling rate, checked positive (a lobe never sampled could not
// carry a path on).
float read_sampling_rate(const Properties& props, const std::string& name);

// (1 - cos)^5, the weight of Schlick's approximation, for cos clamped to [0, 1].
float schlick_weight(float cos);

// Schlick's approximation of a reflectance whose value at normal incidence
// is r0, at a facet seen at cos_i (> 0 outside) of an interface of relative
// index eta (inside over outside). Leaving a denser medium it is taken at the
// refracted cosine, and under total internal reflection it is 1.
Color schlick_fresnel(Color r0, float cos_i, float eta);

// ((eta - 1) / (eta + 1))^2, the reflectance at normal incidence.
float normal_reflectance(float eta);

// Burley's diffuse lobe without its colour and 1/pi: Lambert darkened at
// grazing angles, with retro-reflection growing with roughness, blended by
// `flatness` towards the Hanrahan-Krueger-like "fake subsurface" lobe.
// cos_o and cos_i are the directions' cosines (both > 0), cos_d the cosine
// of either with their half vector.
float burley_diffuse(float cos_o, float cos_i, float cos_d, float roughness, float flatness);

// The diffuse base with its sheen, both scaled by `weight`:
//   weight (base / pi burley_diffuse(...) + sheen lerp(1, tint_of(base), sheen_tint) (1 - cos_d)^5).
Color diffuse_with_sheen(Color base, float weight, float cos_o, float cos_i, float cos_d, float roughness,
                         float flatness, float sheen, float sheen_tint);

// The clearcoat's normal distribution, Burley's generalised Trowbridge-Reitz
// with exponent 1 (isotropic): D(m) = (a^2 - 1) / (pi ln(a^2) (1 + (a^2 - 1) cos^2)).
struct Gtr1 {
  float alpha;
  float D(Vec3 m) const;
  // Draws m with density D(m) cos(theta_m).
  Vec3 sample(Vec2 u) const;
};

// The clearcoat's masking-shadowing: Smith's separable term for GGX with
// alpha 0.25, as the 2012 notes fix it.
float clearcoat_G(Vec3 wo, Vec3 wi, Vec3 m);

// The anisotropic GGX roughness (alpha_u, alpha_v) of the main specular
// lobes: roughness^2 stretched by sqrt(1 - 0.9 anisotropic), at least 0.001.
Vec2 principled_alphas(float roughness, float anisotropic);

}  // namespace caustica
