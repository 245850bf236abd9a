// Radiosity's form factors against closed forms from the radiative heat
// transfer literature (Howell's catalogue: a differential area to a parallel
// rectangle, parallel facing rectangles, perpendicular rectangles sharing an
// edge), computed here from those formulas, not from the code under test;
// and reciprocity, A_i F_ij = A_j F_ji, which the quadrature meets only
// approximately, ever closer as the elements shrink.

#include "integrators/radiosity/form_factor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "integrators/radiosity/element_form_factor.h"
#include "integrators/radiosity/element_mesh.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

constexpr double kPi = std::numbers::pi;

// From a differential area to a parallel a x b rectangle at height c, one
// of whose corners lies straight above it.
double corner_rectangle(double a, double b, double c) {
  const double X = a / c, Y = b / c, sx = std::sqrt(1 + X * X), sy = std::sqrt(1 + Y * Y);
  return (X / sx * std::atan(Y / sx) + Y / sy * std::atan(X / sy)) / (2 * kPi);
}

// Between two directly opposed parallel a x b rectangles a distance c apart.
double parallel_rectangles(double a, double b, double c) {
  const double X = a / c, Y = b / c, x2 = X * X, y2 = Y * Y;
  return 2 / (kPi * X * Y) *
         (std::log(std::sqrt((1 + x2) * (1 + y2) / (1 + x2 + y2))) +
          X * std::sqrt(1 + y2) * std::atan(X / std::sqrt(1 + y2)) +
          Y * std::sqrt(1 + x2) * std::atan(Y / std::sqrt(1 + x2)) - X * std::atan(X) - Y * std::atan(Y));
}

// From a w x l rectangle to an h x l one meeting it at a right angle along
// their common edge of length l.
double perpendicular_rectangles(double w, double h, double l) {
  const double W = w / l, H = h / l, w2 = W * W, h2 = H * H, s = std::sqrt(h2 + w2);
  const double log_term = std::log((1 + w2) * (1 + h2) / (1 + w2 + h2)) +
                          w2 * std::log(w2 * (1 + w2 + h2) / ((1 + w2) * (w2 + h2))) +
                          h2 * std::log(h2 * (1 + h2 + w2) / ((1 + h2) * (h2 + w2)));
  return (W * std::atan(1 / W) + H * std::atan(1 / H) - s * std::atan(1 / s) + log_term / 4) / (kPi * W);
}

// A rectangle as two surface triangles with normal n: corner + s*u + t*v.
std::vector<SurfaceTriangle> rectangle(Vec3 corner, Vec3 u, Vec3 v, Vec3 n) {
  const Vec3 a = corner, b = corner + u, c = corner + u + v, d = corner + v;
  return {{{a, b, c}, {}, n, nullptr}, {{a, c, d}, {}, n, nullptr}};
}

// The form factor between two meshed rectangles, from the elements' ones:
// sum over i, j of A_i F_ij / A_from.
double meshed_form_factor(const std::vector<SurfaceTriangle>& from, const std::vector<SurfaceTriangle>& to,
                          float edge) {
  const auto a = uniform_elements(from, edge), b = uniform_elements(to, edge);
  double area = 0, sum = 0;
  for (const Element& i : a) {
    area += i.area;
    for (const Element& j : b)
      sum += double(i.area) * element_form_factor({&i, from[0].n}, {&j, to[0].n}, nullptr, 0, 0);
  }
  return sum / area;
}

// The unit normal of e on the side toward `target`.
Vec3 facing(const Element& e, Vec3 target) {
  const Vec3 n = normalize(cross(e.p[1] - e.p[0], e.p[2] - e.p[0]));
  return dot(n, target - e.centroid()) > 0 ? n : -n;
}

TEST(PointFormFactor, MatchesTheParallelRectangleFormula) {
  const Vec3 x{0.3f, 0.2f, 0}, n{0, 0, 1};
  // A 1 x 0.6 rectangle at height 0.5 whose corner (0.3, 0.2) is above x,
  // as two triangles: their form factors add.
  const Vec3 a{0.3f, 0.2f, 0.5f}, b{1.3f, 0.2f, 0.5f}, c{1.3f, 0.8f, 0.5f}, d{0.3f, 0.8f, 0.5f};
  const double F = point_to_triangle_form_factor(x, n, {a, b, c}) + point_to_triangle_form_factor(x, n, {a, c, d});
  EXPECT_NEAR(F, corner_rectangle(1.0, 0.6, 0.5), 1e-6);
}

TEST(PointFormFactor, SeesOnlyWhatLiesAboveItsPlane) {
  const Vec3 x{0, 0, 0}, n{0, 0, 1};
  // A vertical rectangle straddling the tangent plane counts as its upper
  // half alone: a 1 x 1 rectangle perpendicular to x's plane, corner at x's
  // foot, from the corner formula rotated (Howell: F = (1/2pi)(atan(1/Y') - ...)).
  const Vec3 a{-1, 1, -1}, b{1, 1, -1}, c{1, 1, 1}, d{-1, 1, 1};
  const double straddling =
      point_to_triangle_form_factor(x, n, {a, b, c}) + point_to_triangle_form_factor(x, n, {a, c, d});
  const Vec3 e{-1, 1, 0}, f{1, 1, 0};
  const double upper = point_to_triangle_form_factor(x, n, {e, f, c}) + point_to_triangle_form_factor(x, n, {e, c, d});
  EXPECT_NEAR(straddling, upper, 1e-9);
  EXPECT_GT(upper, 0);
  EXPECT_EQ(point_to_triangle_form_factor(x, n, {Vec3{0, 0, -1}, Vec3{1, 0, -1}, Vec3{0, 1, -1}}), 0);
}

TEST(PointFormFactor, AHemisphereCoveringTriangleGathersEverything) {
  const double F = point_to_triangle_form_factor(
      {0, 0, 0}, {0, 0, 1}, {Vec3{-1e4f, -1e4f, 1e-3f}, Vec3{1e4f, -1e4f, 1e-3f}, Vec3{0, 2e4f, 1e-3f}});
  EXPECT_NEAR(F, 1.0, 1e-5);
}

TEST(SubtriangleCentroids, SplitTheTriangleEvenly) {
  for (int m : {1, 2, 4}) {
    const auto points = subtriangle_centroids(m);
    ASSERT_EQ(points.size(), size_t(m * m));
    double b1 = 0, b2 = 0;
    for (const Vec2 p : points) {
      EXPECT_GT(p.x, 0);
      EXPECT_GT(p.y, 0);
      EXPECT_LT(p.x + p.y, 1);
      b1 += p.x;
      b2 += p.y;
    }
    // Equal weights integrate linear functions exactly: the centroid.
    EXPECT_NEAR(b1 / points.size(), 1 / 3.0, 1e-6);
    EXPECT_NEAR(b2 / points.size(), 1 / 3.0, 1e-6);
  }
}

TEST(ElementFormFactor, ParallelSquaresConvergeToTheClosedForm) {
  const auto bottom = rectangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1});
  const auto top = rectangle({0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {0, 0, -1});
  const double exact = parallel_rectangles(1, 1, 1);
  ASSERT_NEAR(exact, 0.19982, 1e-5);
  double previous = 1;
  for (const float edge : {1.5f, 0.75f, 0.375f}) {
    const double error = std::abs(meshed_form_factor(bottom, top, edge) - exact);
    EXPECT_LE(error, previous) << "edge " << edge;
    previous = error;
  }
  EXPECT_LT(previous / exact, 2e-3);
}

TEST(ElementFormFactor, PerpendicularRectanglesConvergeToTheClosedForm) {
  // Floor 1 (x) by 2 (z), wall 0.5 high along the common edge z in [0, 2] at x = 0.
  const auto floor = rectangle({0, 0, 0}, {0, 0, 2}, {1, 0, 0}, {0, 1, 0});
  const auto wall = rectangle({0, 0, 0}, {0, 0, 2}, {0, 0.5f, 0}, {1, 0, 0});
  const double exact = perpendicular_rectangles(1, 0.5, 2);
  double previous = 1;
  for (const float edge : {1.2f, 0.6f, 0.3f, 0.15f}) {
    const double error = std::abs(meshed_form_factor(floor, wall, edge) - exact);
    EXPECT_LE(error, previous) << "edge " << edge;
    previous = error;
  }
  EXPECT_LT(previous / exact, 1e-2);
}

TEST(ElementFormFactor, ReciprocityHoldsAsElementsShrink) {
  const auto floor = rectangle({0, 0, 0}, {0, 0, 2}, {1, 0, 0}, {0, 1, 0});
  const auto wall = rectangle({0, 0, 0}, {0, 0, 2}, {0, 0.5f, 0}, {1, 0, 0});
  const double floor_area = 2, wall_area = 1;
  double previous = 1;
  for (const float edge : {1.2f, 0.3f}) {
    const double forward = floor_area * meshed_form_factor(floor, wall, edge);
    const double backward = wall_area * meshed_form_factor(wall, floor, edge);
    const double mismatch = std::abs(forward - backward) / forward;
    EXPECT_LT(mismatch, previous);
    previous = mismatch;
  }
  EXPECT_LT(previous, 1e-2);
  // Two small elements far apart for their size: the rule's error, of the
  // order of (size / distance)^2, bounds the mismatch.
  const Element a =
      uniform_elements({{{Vec3{0, 0, 0}, Vec3{0.1f, 0, 0}, Vec3{0, 0.1f, 0.02f}}, {}, {}, nullptr}}, 1)[0];
  const Element b = uniform_elements(
      {{{Vec3{0.3f, 0.2f, 1}, Vec3{0.2f, 0.3f, 1.1f}, Vec3{0.4f, 0.4f, 0.9f}}, {}, {}, nullptr}}, 1)[0];
  const Vec3 na = facing(a, b.centroid()), nb = facing(b, a.centroid());
  const double ab = a.area * element_form_factor({&a, na}, {&b, nb}, nullptr, 0, 0);
  const double ba = b.area * element_form_factor({&b, nb}, {&a, na}, nullptr, 0, 0);
  ASSERT_GT(ab, 0);
  const float size_over_distance = std::max(a.longest_edge(), b.longest_edge()) / length(a.centroid() - b.centroid());
  EXPECT_NEAR(ab / ba, 1, size_over_distance * size_over_distance);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
