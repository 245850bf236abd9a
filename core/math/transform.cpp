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
      for (int k = 0; k < 4; ++k) sum += m[i][k] * o.m[k][j];
      r.m[i][j] = sum;
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
  // Gauss-Jordan elimination with partial pivoting.
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
      out.m[i][j] = a[i][j + 4];
      // Numerically singular: its inverse would not fit the floats it is applied to.
      if (!(std::abs(out.m[i][j]) < 1e38)) return false;
    }
  return true;
}

Transform::Transform(const Matrix4& m) : m_(m) {
  if (!m.inverse(inv_)) throw std::invalid_argument("transform matrix is singular");
}

Transform Transform::translate(Vec3d d) {
  Matrix4 m = Matrix4::identity(), inv = Matrix4::identity();
  for (int i = 0; i < 3; ++i) {
    m.m[i][3] = d[i];
    inv.m[i][3] = -d[i];
  }
  return {m, inv};
}

namespace {
namespace CAUSTICA_UNITY_ID {

double length(Vec3d v) { return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }
Vec3d normalize(Vec3d v) {
  const double l = length(v);
  return {v.x / l, v.y / l, v.z / l};
}
Vec3d cross(Vec3d a, Vec3d b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
Vec3d difference(Vec3d a, Vec3d b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

Transform Transform::scale(Vec3d s) {
  return Transform(Matrix4{{{{s.x, 0, 0, 0}, {0, s.y, 0, 0}, {0, 0, s.z, 0}, {0, 0, 0, 1}}}});
}

Transform Transform::rotate(Vec3d axis, double degrees) {
  const Vec3d a = normalize(axis);
  const double theta = degrees * 3.14159265358979323846 / 180;
  const double s = std::sin(theta), c = std::cos(theta);
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

Transform Transform::look_at(Vec3d origin, Vec3d target, Vec3d up) {
  if (target == origin) throw std::invalid_argument("lookat: origin and target coincide");
  const Vec3d dir = normalize(difference(target, origin));
  const Vec3d left = cross(normalize(up), dir);
  if (!(length(left) > 1e-12)) throw std::invalid_argument("lookat: 'up' is zero or parallel to the viewing direction");
  const Vec3d l = normalize(left);
  const Vec3d u = cross(dir, l);
  Matrix4 m = Matrix4::identity();
  for (int i = 0; i < 3; ++i) {
    m.m[i][0] = l[i];
    m.m[i][1] = u[i];
    m.m[i][2] = dir[i];
    m.m[i][3] = origin[i];
  }
  return Transform(m);
}

Vec3d Transform::point_double(Vec3d p) const {
  double r[3];
  for (int i = 0; i < 3; ++i) r[i] = m_.m[i][0] * p.x + m_.m[i][1] * p.y + m_.m[i][2] * p.z + m_.m[i][3];
  const double w = m_.m[3][0] * p.x + m_.m[3][1] * p.y + m_.m[3][2] * p.z + m_.m[3][3];
  return w == 1 ? Vec3d(r[0], r[1], r[2]) : Vec3d(r[0] / w, r[1] / w, r[2] / w);
}

Vec3 Transform::point(Vec3d p) const {
  const Vec3d r = point_double(p);
  return {float(r.x), float(r.y), float(r.z)};
}

Vec3 Transform::point_error(Vec3 p) const {
  // Rounding the double result to float dominates; gamma(3) of the terms'
  // magnitudes bounds it with room to spare.
  Vec3 e;
  for (int i = 0; i < 3; ++i)
    e[i] = gamma(3) * float(std::abs(m_.m[i][0] * p.x) + std::abs(m_.m[i][1] * p.y) + std::abs(m_.m[i][2] * p.z) +
                            std::abs(m_.m[i][3]));
  return e;
}

Vec3 Transform::vector(Vec3 v) const {
  Vec3 r;
  for (int i = 0; i < 3; ++i) r[i] = float(m_.m[i][0] * v.x + m_.m[i][1] * v.y + m_.m[i][2] * v.z);
  return r;
}

Vec3 Transform::normal(Vec3 n) const {
  Vec3 r;
  for (int i = 0; i < 3; ++i) r[i] = float(inv_.m[0][i] * n.x + inv_.m[1][i] * n.y + inv_.m[2][i] * n.z);
  return r;
}

}  // namespace caustica
