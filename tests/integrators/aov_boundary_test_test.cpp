// The aov kind boundary_test against Mitsuba 3's definitions worked out in
// the plane z = 0 seen from straight above by an orthographic camera (image
// right is world +x, image top world +y) over [-1.2, 1.2]^2:
//   rectangle [-1, 1]^2     min(1/2 - |x| / 2, 1/2 - |y| / 2)  (its (u, v) to the nearest edge)
//   disk of radius 1        1 - r
//   sphere of radius 1      |cos| between normal and ray, sqrt(1 - r^2)
//   mesh square [-1, 1]^2   3 min(b0, b1, b2), the barycentrics of its triangle
//   with face_normals       (v0 v1 v2 and v0 v2 v3, corners anticlockwise from (-1, -1))
//   the same, instanced     the same (barycentrics do not change with the placement)
//   the same, with vertex   the squared cosine between the normal and the ray: 1
//   normals (computed, as
//   for any mesh without)
// and 1 where the ray misses. A pixel's value is the mean of the function
// at points within its footprint (a box filter), so it lies within L times
// the footprint's half-diagonal of the value at its centre, L the
// function's largest slope there; pixels whose footprint crosses an edge
// or silhouette are not checked.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <string>

#include "tests/support/scratch_dir.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

constexpr int kPixels = 48;
constexpr double kHalfWidth = 1.2;

// A square of half-size h in z = 0, triangles v0 v1 v2 and v0 v2 v3.
std::string square_ply(const std::string& name, double h) {
  const auto path = test::scratch_dir() / (name + ".ply");
  std::ofstream(path) << "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                         "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n"
                      << -h << " " << -h << " 0\n"
                      << h << " " << -h << " 0\n"
                      << h << " " << h << " 0\n"
                      << -h << " " << h << " 0\n3 0 1 2\n3 0 2 3\n";
  return path.string();
}

// 3 min(b) of (x, y) in the square [-1, 1]^2 split along y = x.
double mesh_square(double x, double y) {
  const double b0 = (1 - std::max(x, y)) / 2, b_diag = (1 + std::min(x, y)) / 2, b_side = std::abs(x - y) / 2;
  return 3 * std::min({b0, b_diag, b_side});
}

struct Case {
  std::string what, shape;
  std::function<double(double, double)> value;
  double slope;
  // Whether a point lies on the shape, away from the edges where the slope
  // holds (the sphere's is bounded within r < 0.9).
  std::function<bool(double, double)> inside;
  std::function<bool(double, double)> outside;
};

void check(const Case& c) {
  const std::string xml =
      "<scene version='3.0.0'><integrator type='aov'><string name='aovs' value='b:boundary_test'/></integrator>"
      "<sensor type='orthographic'><transform name='to_world'><scale value='" +
      std::to_string(kHalfWidth) +
      "'/><lookat origin='0, 0, 3' target='0, 0, 0' up='0, 1, 0'/></transform><film type='hdrfilm'><integer "
      "name='width' value='" +
      std::to_string(kPixels) + "'/><integer name='height' value='" + std::to_string(kPixels) +
      "'/><rfilter type='box'/></film></sensor>" + c.shape + "</scene>";
  const auto scene = test::scene_from_xml(xml);
  ASSERT_EQ(scene.integrator->channels(), std::vector<std::string>{"b"});
  const std::vector<float> px = test::render_scene(scene, 4, 5, 2).resolve();
  const double step = 2 * kHalfWidth / kPixels, reach = c.slope * step / std::sqrt(2.0) + 1e-5;
  int on = 0, off = 0;
  for (int j = 0; j < kPixels; ++j)
    for (int i = 0; i < kPixels; ++i) {
      const double x0 = -kHalfWidth + i * step, y1 = kHalfWidth - j * step, x1 = x0 + step, y0 = y1 - step;
      const bool all_in = c.inside(x0, y0) && c.inside(x0, y1) && c.inside(x1, y0) && c.inside(x1, y1);
      const bool all_out = c.outside(x0, y0) && c.outside(x0, y1) && c.outside(x1, y0) && c.outside(x1, y1);
      const float value = px[size_t(j * kPixels + i)];
      if (all_in) {
        EXPECT_NEAR(value, c.value((x0 + x1) / 2, (y0 + y1) / 2), reach)
            << c.what << ", pixel (" << i << ", " << j << ")";
        ++on;
      } else if (all_out) {
        EXPECT_EQ(value, 1.0f) << c.what << ", pixel (" << i << ", " << j << "), a miss";
        ++off;
      }
    }
  EXPECT_GT(on, 400) << c.what;
  EXPECT_GT(off, 50) << c.what;
}

bool in_square(double x, double y) { return std::abs(x) < 1 && std::abs(y) < 1; }
bool out_of_square(double x, double y) { return std::abs(x) > 1 || std::abs(y) > 1; }

TEST(AovBoundaryTest, MitsubasDefinitionsPerShape) {
  const std::string diffuse = "<bsdf type='diffuse'/>", flat = "<boolean name='face_normals' value='true'/>";
  const Case cases[] = {
      {"rectangle", "<shape type='rectangle'>" + diffuse + "</shape>",
       [](double x, double y) { return std::min(0.5 - std::abs(x) / 2, 0.5 - std::abs(y) / 2); }, 0.5, in_square,
       out_of_square},
      {"disk", "<shape type='disk'>" + diffuse + "</shape>", [](double x, double y) { return 1 - std::hypot(x, y); }, 1,
       [](double x, double y) { return std::hypot(x, y) < 1; },
       [](double x, double y) { return std::hypot(x, y) > 1; }},
      {"sphere", "<shape type='sphere'>" + diffuse + "</shape>",
       [](double x, double y) { return std::sqrt(1 - x * x - y * y); }, 2.1,
       [](double x, double y) { return std::hypot(x, y) < 0.9; },
       [](double x, double y) { return std::hypot(x, y) > 1; }},
      {"mesh with face normals",
       "<shape type='ply'><string name='filename' value='" + square_ply("plain_square", 1) + "'/>" + flat + diffuse +
           "</shape>",
       mesh_square, 2.2, in_square, out_of_square},
      {"mesh with vertex normals",
       "<shape type='ply'><string name='filename' value='" + square_ply("plain_square", 1) + "'/>" + diffuse +
           "</shape>",
       [](double, double) { return 1.0; }, 0, in_square, out_of_square},
      {"the mesh instanced",
       "<shape type='shapegroup' id='g'><shape type='ply'><string name='filename' value='" +
           square_ply("half_square", 0.5) + "'/>" + flat + diffuse +
           "</shape></shape><shape type='instance'><ref id='g'/><transform name='to_world'><scale "
           "value='2'/></transform></shape>",
       mesh_square, 2.2, in_square, out_of_square}};
  for (const Case& c : cases) check(c);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
