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

namespace {
namespace CAUSTICA_UNITY_ID {

// The slope x of a visible Beckmann microfacet along the azimuth of a
// direction at polar angle theta, in the configuration stretched to
// alpha = 1 (Heitz and d'Eon 2014). Its density is proportional to
// (cos - x sin) exp(-x^2) for x below cot(theta); the cumulative
//   C(x) = cos (1 + erf x) / 2 + sin exp(-x^2) / (2 sqrt(pi))
// is inverted by Newton's method kept inside a bisection bracket. With
// cos = 1, sin = 0 this is the inverse of the Gaussian cumulative.
double beckmann_visible_slope(double cos_theta, double sin_theta, double u) {
  constexpr double kInvSqrtPi = 0.56418958354775628695;
  // Beyond |x| = 6 the Gaussian holds less than 1e-17 of the mass.
  double lo = -6, hi = 6;
  if (sin_theta > 0) hi = std::min(hi, cos_theta / sin_theta);
  const auto cdf = [&](double x) {
    return 0.5 * cos_theta * (1 + std::erf(x)) + 0.5 * sin_theta * kInvSqrtPi * std::exp(-x * x);
  };
  const double c_lo = cdf(lo), target = c_lo + u * (cdf(hi) - c_lo);
  double x = std::clamp(0.0, lo, hi);
  for (int i = 0; i < 60; ++i) {
    const double value = cdf(x) - target;
    if (value > 0)
      hi = x;
    else
      lo = x;
    const double slope = (cos_theta - sin_theta * x) * kInvSqrtPi * std::exp(-x * x);
    double next = slope > 0 ? x - value / slope : lo - 1;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - x) < 1e-9 || hi - lo < 1e-9) return next;
    x = next;
  }
  return x;
}

// The unit normal of slopes (sx, sy): the facet z = sx x + sy y faces
// (-sx, -sy, 1).
Vec3 normal_from_slopes(double sx, double sy) {
  const double inv = 1 / std::sqrt(1 + sx * sx + sy * sy);
  return {float(-sx * inv), float(-sy * inv), float(inv)};
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

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
  // Visible normals of Beckmann (Heitz and d'Eon 2014): stretch wi to
  // alpha = 1, sample the visible slope along wi's azimuth by inversion and
  // the one across it from the Gaussian, rotate to wi's azimuth, un-stretch.
  const double vx = double(alpha_u_) * wi.x, vy = double(alpha_v_) * wi.y, vz = wi.z;
  const double len_xy = std::sqrt(vx * vx + vy * vy), len = std::sqrt(len_xy * len_xy + vz * vz);
  const double cos_phi = len_xy > 0 ? vx / len_xy : 1, sin_phi = len_xy > 0 ? vy / len_xy : 0;
  const double x = beckmann_visible_slope(vz / len, len_xy / len, u.x);
  const double y = beckmann_visible_slope(1, 0, u.y);
  return normal_from_slopes(alpha_u_ * (cos_phi * x - sin_phi * y), alpha_v_ * (sin_phi * x + cos_phi * y));
}

float MicrofacetDistribution::pdf(Vec3 wi, Vec3 m) const {
  if (wi.z <= 0) return 0;
  return G1(wi, m) * std::max(0.0f, dot(wi, m)) * D(m) / wi.z;
}

Vec3 MicrofacetDistribution::sample_D(Vec2 u) const {
  // The slopes of D(m) cos(theta_m) stretched to alpha = 1 are isotropic:
  // Gaussian for Beckmann, tan^2 = u / (1 - u) for GGX.
  const double v = std::max(1.0 - u.x, 1e-30);
  const double radius = type_ == Type::GGX ? std::sqrt(u.x / v) : std::sqrt(-std::log(v));
  const double phi = 2 * double(kPi) * u.y;
  return normal_from_slopes(alpha_u_ * radius * std::cos(phi), alpha_v_ * radius * std::sin(phi));
}

float MicrofacetDistribution::pdf_D(Vec3 m) const { return D(m) * std::max(0.0f, m.z); }

}  // namespace caustica
