#include "core/bsdf/microfacet.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/math/constants.h"

namespace caustica {

MicrofacetDistribution::MicrofacetDistribution(Type type, float alpha_u, float alpha_v)
    // Alphas below 1e-4 make D overflow in single precision; such a surface
    // is smooth for every practical purpose.
    : type_(type), alpha_u_(std::max(alpha_u, 1e-4f)), alpha_v_(std::max(alpha_v, 1e-4f)) {}

MicrofacetDistribution::Type MicrofacetDistribution::parse_type(const std::string& name) {
  if (name == "beckmann") return Type::Beckmann;
  if (name == "ggx") return Type::GGX;
  throw std::invalid_argument("distribution must be beckmann or ggx, not '" + name + "'");
}

float MicrofacetDistribution::D(Vec3 m) const {
  if (m.z <= 0) return 0;
  const float x = m.x / alpha_u_, y = m.y / alpha_v_, z2 = m.z * m.z;
  if (type_ == Type::GGX) {
    const float d = x * x + y * y + z2;
    return 1 / (kPi * alpha_u_ * alpha_v_ * d * d);
  }
  // exp(-tan^2 / alpha^2) / cos^4 in log space: near the horizon the two
  // factors would underflow and overflow into 0 * inf.
  const float e = (x * x + y * y) / z2;
  if (!(e < 1e4f)) return 0;  // also where z2 underflows
  return std::exp(-e - 2 * std::log(z2)) / (kPi * alpha_u_ * alpha_v_);
}

float MicrofacetDistribution::lambda(Vec3 w) const {
  // alpha^2 tan^2(theta) along w's azimuth.
  const float z2 = w.z * w.z;
  if (z2 == 0) return kInfinity;
  const float a2t2 = (w.x * w.x * alpha_u_ * alpha_u_ + w.y * w.y * alpha_v_ * alpha_v_) / z2;
  if (type_ == Type::GGX) return 0.5f * (std::sqrt(1 + a2t2) - 1);
  if (a2t2 == 0) return 0;
  const float a = 1 / std::sqrt(a2t2);
  return 0.5f * (std::erf(a) - 1) + std::exp(-a * a) / (2 * a * std::sqrt(kPi));
}

float MicrofacetDistribution::G1(Vec3 w, Vec3 m) const {
  // A facet seen from its back, or from below the macrosurface, is hidden.
  if (dot(w, m) * w.z <= 0) return 0;
  return 1 / (1 + lambda(w));
}

float MicrofacetDistribution::G(Vec3 wo, Vec3 wi, Vec3 m) const {
  if (dot(wo, m) * wo.z <= 0 || dot(wi, m) * wi.z <= 0) return 0;
  return 1 / (1 + lambda(wo) + lambda(wi));
}

Vec3 MicrofacetDistribution::sample(Vec3 wi, Vec2 u) const {
  if (type_ == Type::GGX) {
    // Visible normals of GGX (Heitz, JCGT 2018): in the configuration
    // stretched to alpha = 1 the visible normals are a hemisphere seen from
    // wi, i.e. a projected disk, sampled and then un-stretched.
    const Vec3 v = normalize(Vec3(alpha_u_ * wi.x, alpha_v_ * wi.y, wi.z));
    const float len2 = v.x * v.x + v.y * v.y;
    const Vec3 t1 = len2 > 0 ? Vec3(-v.y, v.x, 0) / std::sqrt(len2) : Vec3(1, 0, 0);
    const Vec3 t2 = cross(v, t1);
    const float r = std::sqrt(u.x), phi = 2 * kPi * u.y;
    const float p1 = r * std::cos(phi);
    const float s = 0.5f * (1 + v.z);
    const float p2 = (1 - s) * std::sqrt(std::max(0.0f, 1 - p1 * p1)) + s * r * std::sin(phi);
    const Vec3 n = t1 * p1 + t2 * p2 + v * std::sqrt(std::max(0.0f, 1 - p1 * p1 - p2 * p2));
    return normalize(Vec3(alpha_u_ * n.x, alpha_v_ * n.y, std::max(1e-6f, n.z)));
  }
  // Beckmann: the slopes of D(m) cos(theta_m) are Gaussian.
  const float radius = std::sqrt(-std::log(std::max(1 - u.x, 1e-30f)));
  const float phi = 2 * kPi * u.y;
  return normalize(Vec3(-alpha_u_ * radius * std::cos(phi), -alpha_v_ * radius * std::sin(phi), 1));
}

float MicrofacetDistribution::pdf(Vec3 wi, Vec3 m) const {
  if (type_ == Type::GGX) {
    if (wi.z <= 0) return 0;
    return G1(wi, m) * std::max(0.0f, dot(wi, m)) * D(m) / wi.z;
  }
  return D(m) * std::max(0.0f, m.z);
}

}  // namespace caustica
