#include "core/math/transform.h"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "core/math/constants.h"

namespace caustica {

Matrix4 Matrix4::identity() {
  Matrix4 r;
  for (int i = 0; i < 4; ++i) r.m[i][i] = 1;
  return r;
}

Matrix4 Matrix4::operator*(const Matrix4& o) const {
  Matrix4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      double sum = 0;
      for (int k = 0; k < 4; ++k) sum += double(m[i][k]) * o.m[k][j];
      r.m[i][j] = float(sum);
    }
  return r;
}

Matrix4 Matrix4::transposed() const {
  Matrix4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r.m[i][j] = m[j][i];
  return r;
}

bool Matrix4::inverse(Matrix4& out) const {
  // Gauss-Jordan elimination with partial pivoting, in double precision so
  // that scenes with huge or tiny scales keep an accurate inverse.
  double a[4][8];
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      a[i][j] = m[i][j];
      a[i][j + 4] = i == j ? 1 : 0;
    }
  for (int col = 0; col < 4; ++col) {
    int pivot = col;
    for (int r = col + 1; r < 4; ++r)
      if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
    if (a[pivot][col] == 0) return false;
    std::swap(a[col], a[pivot]);
    const double inv = 1 / a[col][col];
    for (double& v : a[col]) v *= inv;
    for (int r = 0; r < 4; ++r) {
      if (r == col) continue;
      const double f = a[r][col];
      for (int j = 0; j < 8; ++j) a[r][j] -= f * a[col][j];
    }
  }
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      out.m[i][j] = float(a[i][j + 4]);
      if (!std::isfinite(out.m[i][j])) return false;  // numerically singular
    }
  return true;
}

Transform::Transform(const Matrix4& m) : m_(m) {
  if (!m.inverse(inv_)) throw std::invalid_argument("transform matrix is singular");
}

Transform Transform::translate(Vec3 d) {
  Matrix4 m = Matrix4::identity(), inv = Matrix4::identity();
  for (int i = 0; i < 3; ++i) {
    m.m[i][3] = d[i];
    inv.m[i][3] = -d[i];
  }
  return {m, inv};
}

Transform Transform::scale(Vec3 s) {
  return Transform(Matrix4{{{{s.x, 0, 0, 0}, {0, s.y, 0, 0}, {0, 0, s.z, 0}, {0, 0, 0, 1}}}});
}

Transform Transform::rotate(Vec3 axis, float degrees) {
  const Vec3 a = normalize(axis);
  const float theta = degrees * kPi / 180;
  const float s = std::sin(theta), c = std::cos(theta);
  Matrix4 m = Matrix4::identity();
  m.m[0][0] = a.x * a.x + (1 - a.x * a.x) * c;
  m.m[0][1] = a.x * a.y * (1 - c) - a.z * s;
  m.m[0][2] = a.x * a.z * (1 - c) + a.y * s;
  m.m[1][0] = a.x * a.y * (1 - c) + a.z * s;
  m.m[1][1] = a.y * a.y + (1 - a.y * a.y) * c;
  m.m[1][2] = a.y * a.z * (1 - c) - a.x * s;
  m.m[2][0] = a.x * a.z * (1 - c) - a.y * s;
  m.m[2][1] = a.y * a.z * (1 - c) + a.x * s;
  m.m[2][2] = a.z * a.z + (1 - a.z * a.z) * c;
  return {m, m.transposed()};
}

Transform Transform::look_at(Vec3 origin, Vec3 target, Vec3 up) {
  if (target == origin) throw std::invalid_argument("lookat: origin and target coincide");
  const Vec3 dir = normalize(target - origin);
  const Vec3 left = cross(normalize(up), dir);
  if (!(squared_length(left) > 0))
    throw std::invalid_argument("lookat: 'up' is zero or parallel to the viewing direction");
  const Vec3 l = normalize(left);
  const Vec3 u = cross(dir, l);
  Matrix4 m = Matrix4::identity();
  for (int i = 0; i < 3; ++i) {
    m.m[i][0] = l[i];
    m.m[i][1] = u[i];
    m.m[i][2] = dir[i];
    m.m[i][3] = origin[i];
  }
  return Transform(m);
}

Vec3 Transform::point(Vec3 p) const {
  Vec3 r;
  for (int i = 0; i < 3; ++i) r[i] = m_.m[i][0] * p.x + m_.m[i][1] * p.y + m_.m[i][2] * p.z + m_.m[i][3];
  const float w = m_.m[3][0] * p.x + m_.m[3][1] * p.y + m_.m[3][2] * p.z + m_.m[3][3];
  return w == 1 ? r : r / w;
}

Vec3 Transform::point_error(Vec3 p) const {
  Vec3 e;
  for (int i = 0; i < 3; ++i)
    e[i] = gamma(3) * (std::abs(m_.m[i][0] * p.x) + std::abs(m_.m[i][1] * p.y) + std::abs(m_.m[i][2] * p.z) +
                       std::abs(m_.m[i][3]));
  return e;
}

Vec3 Transform::vector(Vec3 v) const {
  Vec3 r;
  for (int i = 0; i < 3; ++i) r[i] = m_.m[i][0] * v.x + m_.m[i][1] * v.y + m_.m[i][2] * v.z;
  return r;
}

Vec3 Transform::normal(Vec3 n) const {
  Vec3 r;
  for (int i = 0; i < 3; ++i) r[i] = inv_.m[0][i] * n.x + inv_.m[1][i] * n.y + inv_.m[2][i] * n.z;
  return r;
}

}  // namespace caustica
