#include "core/lights/light_bounds.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/math/constants.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

float sin_from_cos(float c) { return std::sqrt(std::max(0.0f, 1 - c * c)); }

// cos(max(0, a - b)) for angles a, b in [0, pi] given by their cosines.
float cos_of_excess(float cos_a, float cos_b) {
  if (cos_a >= cos_b) return 1;
  return cos_a * cos_b + sin_from_cos(cos_a) * sin_from_cos(cos_b);
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

LightBounds LightBounds::merge(const LightBounds& a, const LightBounds& b) {
  LightBounds m;
  m.bounds = a.bounds;
  m.bounds.expand(b.bounds);
  m.phi = a.phi + b.phi;
  m.cos_theta_e = std::min(a.cos_theta_e, b.cos_theta_e);
  if (a.cos_theta_o <= -1 || b.cos_theta_o <= -1) return m;
  // The smallest cone around both cones of directions.
  const float theta_a = std::acos(std::clamp(a.cos_theta_o, -1.0f, 1.0f));
  const float theta_b = std::acos(std::clamp(b.cos_theta_o, -1.0f, 1.0f));
  const float cos_d = std::clamp(dot(a.axis, b.axis), -1.0f, 1.0f);
  const float theta_d = std::acos(cos_d);
  if (theta_d + theta_b <= theta_a) {
    m.axis = a.axis;
    m.cos_theta_o = a.cos_theta_o;
    return m;
  }
  if (theta_d + theta_a <= theta_b) {
    m.axis = b.axis;
    m.cos_theta_o = b.cos_theta_o;
    return m;
  }
  const float theta_o = (theta_a + theta_d + theta_b) / 2;
  const Vec3 toward_b = b.axis - a.axis * cos_d;
  if (theta_o >= kPi || !(length(toward_b) > 1e-6f)) return m;
  const float turn = theta_o - theta_a;
  m.axis = normalize(a.axis * std::cos(turn) + normalize(toward_b) * std::sin(turn));
  m.cos_theta_o = std::cos(theta_o);
  return m;
}

float light_importance(const LightBounds& b, Vec3 p, Vec3 n) {
  return light_importance(b, b.bounds.center(), bounding_radius(b.bounds), p, n);
}

float light_importance(const LightBounds& b, Vec3 c, float r, Vec3 p, Vec3 n) {
  const Vec3 v = p - c;
  const float d2 = dot(v, v);
  if (d2 <= r * r) return b.phi / std::max(r * r, 1e-20f);
  const float d = std::sqrt(d2);
  const Vec3 toward_p = v / d;
  const float cos_u = std::sqrt(std::max(0.0f, 1 - r * r / d2));  // half the angle the bounding sphere spans at p

  float cos_emit = 1;
  if (b.cos_theta_o > -1) {
    // The angle between the cone and p, less what the bounding sphere spans.
    cos_emit = cos_of_excess(cos_of_excess(dot(b.axis, toward_p), b.cos_theta_o), cos_u);
    if (cos_emit < b.cos_theta_e) return 0;
  }
  float cos_receive = 1;
  if (n.x != 0 || n.y != 0 || n.z != 0) cos_receive = cos_of_excess(std::abs(dot(n, toward_p)), cos_u);
  const float importance = b.phi * std::max(cos_emit, 0.0f) * cos_receive / std::max(d2, 1e-20f);
  return std::isfinite(importance) ? importance : std::numeric_limits<float>::max();
}

}  // namespace caustica
