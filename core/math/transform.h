#pragma once

#include <array>

#include "core/math/vec.h"

namespace caustica {

// A point or vector in double precision: what transforms are composed and
// applied in, so that a scene far from the origin loses nothing before its
// geometry is stored, relative to the camera, in float.
struct Vec3d {
  double x = 0, y = 0, z = 0;
  constexpr Vec3d() = default;
  constexpr Vec3d(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}
  constexpr Vec3d(Vec3 v) : x(v.x), y(v.y), z(v.z) {}  // NOLINT: widening is exact
  constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr Vec3d operator-() const { return {-x, -y, -z}; }
  constexpr bool operator==(const Vec3d&) const = default;
};

// A row-major 4x4 matrix acting on column vectors, in double precision.
struct Matrix4 {
  std::array<std::array<double, 4>, 4> m{};

  static Matrix4 identity();
  Matrix4 operator*(const Matrix4& o) const;
  Matrix4 transposed() const;
  // Returns false for a singular matrix.
  bool inverse(Matrix4& out) const;
  bool operator==(const Matrix4&) const = default;
};

// An affine map with its inverse kept alongside, as loaded from `to_world`.
class Transform {
 public:
  Transform() = default;
  explicit Transform(const Matrix4& m);  // throws std::invalid_argument if singular
  Transform(const Matrix4& m, const Matrix4& inv) : m_(m), inv_(inv) {}

  static Transform translate(Vec3d d);
  static Transform scale(Vec3d s);
  static Transform rotate(Vec3d axis, double degrees);
  // Camera-style frame at `origin` looking at `target`; local +z points to
  // the target, +y is up and +x is to the left (Mitsuba's convention).
  static Transform look_at(Vec3d origin, Vec3d target, Vec3d up);

  Transform operator*(const Transform& o) const { return {m_ * o.m_, o.inv_ * inv_}; }
  Transform inverse() const { return {inv_, m_}; }

  // Computed in double, rounded once to float.
  Vec3 point(Vec3d p) const;
  Vec3d point_double(Vec3d p) const;
  Vec3 vector(Vec3 v) const;
  // Normals transform by the inverse transpose; the result is not normalised.
  Vec3 normal(Vec3 n) const;
  // Bound on the rounding error of point(p), per axis.
  Vec3 point_error(Vec3 p) const;

  const Matrix4& matrix() const { return m_; }
  const Matrix4& inverse_matrix() const { return inv_; }
  bool is_identity() const { return m_ == Matrix4::identity(); }

 private:
  Matrix4 m_ = Matrix4::identity();
  Matrix4 inv_ = Matrix4::identity();
};

}  // namespace caustica
