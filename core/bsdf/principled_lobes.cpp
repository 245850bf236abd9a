#include "core/bsdf/principled_lobes.h"

#include <algorithm>
#include <cmath>

#include "core/math/constants.h"
#include "core/registry/properties.h"

namespace caustica {

Color tint_of(Color base) {
  const float lum = base.luminance();
  return lum > 0 ? base / lum : Color(1);
}

float read_sampling_rate(const Properties& props, const std::string& name) {
  const float rate = props.get_float(name);
  if (!(rate > 0) || !std::isfinite(rate))
    throw props.error(name, "must be positive (a lobe never sampled could not carry a path on)");
  return rate;
}

float schlick_weight(float cos) {
  const float m = std::clamp(1 - cos, 0.0f, 1.0f);
  const float m2 = m * m;
  return m2 * m2 * m;
}

Color schlick_fresnel(Color r0, float cos_i, float eta) {
  const float eta_it = cos_i >= 0 ? eta : 1 / eta;
  float cos = std::abs(cos_i);
  // Leaving the denser side the reflectance follows the refracted angle.
  if (eta_it < 1) {
    const float cos_t2 = 1 - (1 - cos * cos) / (eta_it * eta_it);
    cos = cos_t2 > 0 ? std::sqrt(cos_t2) : 0;
  }
  const float w = schlick_weight(cos);
  return r0 * (1 - w) + Color(w);
}

float normal_reflectance(float eta) {
  const float r = (eta - 1) / (eta + 1);
  return r * r;
}

float burley_diffuse(float cos_o, float cos_i, float cos_d, float roughness, float flatness) {
  const float f_o = schlick_weight(cos_o), f_i = schlick_weight(cos_i);
  const float rr = 2 * roughness * cos_d * cos_d;
  const float lambert = (1 - 0.5f * f_o) * (1 - 0.5f * f_i);
  const float retro = rr * (f_o + f_i + f_o * f_i * (rr - 1));
  if (flatness <= 0) return lambert + retro;
  const float f_ss90 = 0.5f * rr;
  const float f_ss = (1 + (f_ss90 - 1) * f_o) * (1 + (f_ss90 - 1) * f_i);
  const float subsurface = 1.25f * (f_ss * (1 / (cos_o + cos_i) - 0.5f) + 0.5f);
  return (1 - flatness) * (lambert + retro) + flatness * subsurface;
}

Color diffuse_with_sheen(Color base, float weight, float cos_o, float cos_i, float cos_d, float roughness,
                         float flatness, float sheen, float sheen_tint) {
  Color f = base * (kInvPi * burley_diffuse(cos_o, cos_i, cos_d, roughness, flatness));
  if (sheen > 0) f += (Color(1) * (1 - sheen_tint) + tint_of(base) * sheen_tint) * (sheen * schlick_weight(cos_d));
  return f * weight;
}

float Gtr1::D(Vec3 m) const {
  if (m.z <= 0) return 0;
  const float a2 = alpha * alpha;
  return (a2 - 1) / (kPi * std::log(a2) * (1 + (a2 - 1) * m.z * m.z));
}

Vec3 Gtr1::sample(Vec2 u) const {
  const float a2 = alpha * alpha;
  const float cos2 = std::clamp((1 - std::pow(a2, 1 - u.y)) / (1 - a2), 0.0f, 1.0f);
  const float cos = std::sqrt(cos2), sin = std::sqrt(1 - cos2);
  const float phi = 2 * kPi * u.x;
  return {sin * std::cos(phi), sin * std::sin(phi), cos};
}

namespace {
namespace CAUSTICA_UNITY_ID {

float smith_ggx_g1(Vec3 w, Vec3 m, float alpha) {
  if (dot(w, m) * w.z <= 0) return 0;
  const float c2 = w.z * w.z, t2 = std::max(0.0f, 1 - c2) / c2;
  return 2 / (1 + std::sqrt(1 + alpha * alpha * t2));
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

float clearcoat_G(Vec3 wo, Vec3 wi, Vec3 m) { return smith_ggx_g1(wo, m, 0.25f) * smith_ggx_g1(wi, m, 0.25f); }

Vec2 principled_alphas(float roughness, float anisotropic) {
  const float r2 = roughness * roughness, aspect = std::sqrt(1 - 0.9f * anisotropic);
  return {std::max(0.001f, r2 / aspect), std::max(0.001f, r2 * aspect)};
}

}  // namespace caustica
