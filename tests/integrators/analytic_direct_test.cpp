// Images known in closed form: a diffuse plane lit by a directional light
// alone, where every pixel that sees the plane shows reflectance / pi x
// irradiance x |cos| between the light and the shading normal, whatever the
// samples (next-event estimation toward a delta light draws nothing that
// changes its value). A second oracle beside the cross-integrator tests:
//  - next-event cosines with shading normals (tests/integrators/
//    shading_normals_test.cpp holds them by ptracer and bdpt agreeing with
//    path): a plane whose vertex normals, or whose normal map, lean 30
//    degrees, read with the shading normal's cosine, not the geometric one;
//  - the ray offset's error term (tests/shapes hold the bound against the
//    exact hit point): a tilted plane 3.7e5 from the origin lit at 80
//    degrees from its normal, where a shadow ray leaving without the offset
//    re-hits the plane it left and blackens the pixel (acne).

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/math/constants.h"
#include "tests/support/scratch_dir.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

constexpr double kReflectance = 0.5, kIrradiance = 3;

std::string number(double x) {
  char s[64];
  std::snprintf(s, sizeof s, "%.17g", x);
  return s;
}

// A PLY square with corners c +- a t1 +- a t2 and, if given, one normal at
// every vertex.
std::string square_ply(const std::string& name, const double c[3], const double t1[3], const double t2[3], double a,
                       const double* normal) {
  const auto path = test::scratch_dir() / (name + ".ply");
  std::ofstream out(path);
  out << "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n";
  if (normal) out << "property float nx\nproperty float ny\nproperty float nz\n";
  out << "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const int corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (const auto& k : corner) {
    for (int i = 0; i < 3; ++i) out << number(c[i] + a * (k[0] * t1[i] + k[1] * t2[i])) << " ";
    if (normal)
      for (int i = 0; i < 3; ++i) out << number(normal[i]) << " ";
    out << "\n";
  }
  out << "4 0 1 2 3\n";
  return path.string();
}

std::string diffuse() {
  return "<bsdf type='diffuse'><rgb name='reflectance' value='" + number(kReflectance) + "'/></bsdf>";
}

// The scene: `plane`, a camera at `eye` looking at `target` (up +z unless
// told), and a directional light travelling along -to_light.
std::string lit_plane(const std::string& integrator, const std::string& plane, const double eye[3],
                      const double target[3], const double to_light[3], const std::string& up = "0, 0, 1") {
  const auto v = [](const double p[3]) { return number(p[0]) + ", " + number(p[1]) + ", " + number(p[2]); };
  return "<scene version='3.0.0'><integrator type='" + integrator +
         "'/><sensor type='perspective'><float name='fov' value='30'/><transform name='to_world'><lookat origin='" +
         v(eye) + "' target='" + v(target) + "' up='" + up +
         "'/></transform><film type='hdrfilm'><integer name='width' value='16'/><integer name='height' value='16'/>"
         "<rfilter type='box'/></film></sensor>" +
         plane + "<emitter type='directional'><vector name='direction' x='" + number(-to_light[0]) + "' y='" +
         number(-to_light[1]) + "' z='" + number(-to_light[2]) + "'/><rgb name='irradiance' value='" +
         number(kIrradiance) + "'/></emitter></scene>";
}

// Every pixel of the render equals `expected` to float precision.
void expect_uniform(const std::string& xml, double expected, const std::string& what) {
  const auto film = test::render_scene(test::scene_from_xml(xml), 4, 7, 2);
  const std::vector<float> px = film.resolve();
  int off = 0;
  for (size_t i = 0; i < px.size(); ++i)
    if (!(std::abs(px[i] - expected) <= 2e-5 * expected)) ++off;
  EXPECT_EQ(off, 0) << what << ": of " << px.size() << " values, " << off << " differ from " << expected
                    << " (first pixel " << px[0] << ")";
}

// The light 45 degrees toward +x: cos 45 = 0.707 to the geometric normal,
// cos 15 = 0.966 to a shading normal leaning 30 degrees toward +x.
TEST(AnalyticDirect, NextEventEstimationUsesTheShadingNormalsCosine) {
  const double up[3] = {0, 0, 1}, lean[3] = {0.5, 0, std::sqrt(0.75)};
  const double c[3] = {0, 0, 0}, x[3] = {1, 0, 0}, y[3] = {0, 1, 0};
  const double eye[3] = {0, -3, 6}, target[3] = {0, 0, 0};
  const double to_light[3] = {std::sqrt(0.5), 0, std::sqrt(0.5)};
  const double expected = kReflectance / kPi * kIrradiance * (lean[0] * to_light[0] + lean[2] * to_light[2]);
  const std::string vertex_normals = "<shape type='ply'><string name='filename' value='" +
                                     square_ply("leaning_normals", c, x, y, 8, lean) + "'/>" + diffuse() + "</shape>";
  // 2 c - 1 = (0.5, 0, 0.866) in the rectangle's tangent frame (+x, +y, +z).
  const std::string normal_map =
      "<shape type='rectangle'><transform name='to_world'><scale value='8'/></transform>"
      "<bsdf type='normalmap'><rgb name='normalmap' value='0.75, 0.5, 0.9330127'/>" +
      diffuse() + "</bsdf></shape>";
  for (const char* integrator : {"direct", "path"}) {
    expect_uniform(lit_plane(integrator, vertex_normals, eye, target, to_light), expected,
                   std::string(integrator) + ", vertex normals");
    expect_uniform(lit_plane(integrator, normal_map, eye, target, to_light), expected,
                   std::string(integrator) + ", normal map");
  }
  // Without the lean, the geometric cosine.
  const std::string flat = "<shape type='ply'><string name='filename' value='" +
                           square_ply("flat_normals", c, x, y, 8, up) + "'/>" + diffuse() + "</shape>";
  expect_uniform(lit_plane("direct", flat, eye, target, to_light), kReflectance / kPi * kIrradiance * to_light[2],
                 "flat");
}

// A plane tilted off every axis, 3.7e5 from the origin, lit 80 degrees from
// its normal: the hit points carry rounding errors of about 0.03, so each
// shadow ray must leave by more than that, and only the error bound says
// by how much.
TEST(AnalyticDirect, NoAcneFarFromTheOrigin) {
  const double norm = std::sqrt(14.0);
  const double n[3] = {1 / norm, 2 / norm, 3 / norm};
  // t1 = normalize(z x n), t2 = n x t1: a frame of the plane.
  const double len = std::hypot(n[0], n[1]);
  const double t1[3] = {-n[1] / len, n[0] / len, 0};
  const double t2[3] = {n[1] * t1[2] - n[2] * t1[1], n[2] * t1[0] - n[0] * t1[2], n[0] * t1[1] - n[1] * t1[0]};
  const double c[3] = {1e5, -2e5, 3e5};
  const double eye[3] = {c[0] + 60 * n[0], c[1] + 60 * n[1], c[2] + 60 * n[2]};
  const double a = 80 * kPi / 180;
  const double to_light[3] = {std::cos(a) * n[0] + std::sin(a) * t1[0], std::cos(a) * n[1] + std::sin(a) * t1[1],
                              std::cos(a) * n[2] + std::sin(a) * t1[2]};
  const std::string plane = "<shape type='ply'><string name='filename' value='" +
                            square_ply("far_plane", c, t1, t2, 50, nullptr) + "'/>" + diffuse() + "</shape>";
  const std::string up = number(t2[0]) + ", " + number(t2[1]) + ", " + number(t2[2]);
  for (const char* integrator : {"direct", "path"})
    expect_uniform(lit_plane(integrator, plane, eye, c, to_light, up), kReflectance / kPi * kIrradiance * std::cos(a),
                   integrator);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
