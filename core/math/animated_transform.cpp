#include "core/math/animated_transform.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

using Mat3 = std::array<std::array<double, 3>, 3>;

// The rotation matrix's unit quaternion (w, x, y, z), from its largest
// component for accuracy.
std::array<double, 4> quaternion_of(const Mat3& r) {
  const double trace = r[0][0] + r[1][1] + r[2][2];
  std::array<double, 4> q;
  if (trace > 0) {
    const double s = 2 * std::sqrt(1 + trace);
    q = {s / 4, (r[2][1] - r[1][2]) / s, (r[0][2] - r[2][0]) / s, (r[1][0] - r[0][1]) / s};
  } else if (r[0][0] > r[1][1] && r[0][0] > r[2][2]) {
    const double s = 2 * std::sqrt(1 + r[0][0] - r[1][1] - r[2][2]);
    q = {(r[2][1] - r[1][2]) / s, s / 4, (r[0][1] + r[1][0]) / s, (r[0][2] + r[2][0]) / s};
  } else if (r[1][1] > r[2][2]) {
    const double s = 2 * std::sqrt(1 + r[1][1] - r[0][0] - r[2][2]);
    q = {(r[0][2] - r[2][0]) / s, (r[0][1] + r[1][0]) / s, s / 4, (r[1][2] + r[2][1]) / s};
  } else {
    const double s = 2 * std::sqrt(1 + r[2][2] - r[0][0] - r[1][1]);
    q = {(r[1][0] - r[0][1]) / s, (r[0][2] + r[2][0]) / s, (r[1][2] + r[2][1]) / s, s / 4};
  }
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (double& c : q) c /= n;
  return q;
}

Mat3 rotation_of(const std::array<double, 4>& q) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  return {{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
           {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
           {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}}};
}

// Spherical linear interpolation; nearly equal rotations interpolate
// linearly (then normalised), where the arc's sine vanishes.
std::array<double, 4> slerp(const std::array<double, 4>& a, const std::array<double, 4>& b, double f) {
  const double cos_angle = std::clamp(a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3], -1.0, 1.0);
  std::array<double, 4> q;
  if (cos_angle > 0.9995) {
    for (int i = 0; i < 4; ++i) q[i] = a[i] + f * (b[i] - a[i]);
  } else {
    const double angle = std::acos(cos_angle), sin_angle = std::sin(angle);
    const double wa = std::sin((1 - f) * angle) / sin_angle, wb = std::sin(f * angle) / sin_angle;
    for (int i = 0; i < 4; ++i) q[i] = wa * a[i] + wb * b[i];
  }
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (double& c : q) c /= n;
  return q;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

// Gram-Schmidt on the linear part's columns gives A = Q S with S upper
// triangular and positive on its diagonal; a reflection (det Q = -1) moves
// into S as a negative last scale, so that Q is a rotation.
TransformParts TransformParts::of(const Transform& transform) {
  const Matrix4& m = transform.matrix();
  Mat3 a;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) a[i][j] = m.m[i][j];
  Mat3 q{}, s{};
  for (int j = 0; j < 3; ++j) {
    std::array<double, 3> v{a[0][j], a[1][j], a[2][j]};
    for (int k = 0; k < j; ++k) {
      const double d = q[0][k] * a[0][j] + q[1][k] * a[1][j] + q[2][k] * a[2][j];
      s[k][j] = d;
      for (int i = 0; i < 3; ++i) v[i] -= d * q[i][k];
    }
    const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (!(n > 1e-300)) throw std::invalid_argument("the transform is singular");
    s[j][j] = n;
    for (int i = 0; i < 3; ++i) q[i][j] = v[i] / n;
  }
  const double det = q[0][0] * (q[1][1] * q[2][2] - q[1][2] * q[2][1]) -
                     q[0][1] * (q[1][0] * q[2][2] - q[1][2] * q[2][0]) +
                     q[0][2] * (q[1][0] * q[2][1] - q[1][1] * q[2][0]);
  if (det < 0) {
    for (int i = 0; i < 3; ++i) q[i][2] = -q[i][2];
    for (int j = 0; j < 3; ++j) s[2][j] = -s[2][j];
  }
  TransformParts parts;
  parts.s = s;
  parts.q = quaternion_of(q);
  parts.t = {m.m[0][3], m.m[1][3], m.m[2][3]};
  return parts;
}

Transform TransformParts::transform() const {
  const Mat3 r = rotation_of(q);
  Matrix4 m = Matrix4::identity();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      double v = 0;
      for (int k = 0; k < 3; ++k) v += r[i][k] * s[k][j];
      m.m[i][j] = v;
    }
    m.m[i][3] = t[i];
  }
  return Transform(m);
}

AnimatedTransform::AnimatedTransform(const std::vector<Transform>& keys) {
  for (const Transform& key : keys) {
    TransformParts parts = TransformParts::of(key);
    if (!parts_.empty()) {
      const auto& q = parts_.back().q;
      if (q[0] * parts.q[0] + q[1] * parts.q[1] + q[2] * parts.q[2] + q[3] * parts.q[3] < 0)
        for (double& c : parts.q) c = -c;
    }
    parts_.push_back(parts);
  }
}

size_t AnimatedTransform::first_rescaled_key() const {
  for (size_t k = 1; k < parts_.size(); ++k)
    for (int i = 0; i < 3; ++i)
      for (int j = i; j < 3; ++j)
        if (std::abs(parts_[k].s[i][j] - parts_[0].s[i][j]) > 1e-4 * std::abs(parts_[0].s[i][i])) return k + 1;
  return 0;
}

Transform AnimatedTransform::at(double time) const {
  if (parts_.size() == 1) return parts_[0].transform();
  const double x = std::clamp(time, 0.0, 1.0) * double(parts_.size() - 1);
  const size_t k = std::min(size_t(x), parts_.size() - 2);
  const double f = x - double(k);
  const TransformParts &a = parts_[k], &b = parts_[k + 1];
  TransformParts p;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) p.s[i][j] = a.s[i][j] + f * (b.s[i][j] - a.s[i][j]);
    p.t[i] = a.t[i] + f * (b.t[i] - a.t[i]);
  }
  p.q = slerp(a.q, b.q, f);
  return p.transform();
}

}  // namespace caustica
