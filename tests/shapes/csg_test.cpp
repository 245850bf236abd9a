// csg: the boolean combination of crossings along a line (worked by hand),
// the closure check of mesh operands, the volume of solids measured by
// casting rays through the scene against their closed forms (which also
// checks that every boundary faces out: rays alternate entering and
// leaving), and the refusals.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "core/math/constants.h"
#include "core/shapes/csg_combine.h"
#include "core/shapes/mesh_closure.h"
#include "tests/support/test_scenes.h"
#include "tests/support/thrown_message.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using testing::HasSubstr;

// An operand's crossings: inside between consecutive pairs of ts.
std::vector<BoundaryCrossing> intervals(std::initializer_list<double> ts, uint32_t leaf) {
  std::vector<BoundaryCrossing> out;
  bool entering = true;
  for (double t : ts) {
    out.push_back({t, leaf, 0, {}, entering});
    entering = !entering;
  }
  return out;
}

// (t, leaf, entering) of each crossing.
std::vector<std::tuple<double, uint32_t, bool>> summary(const std::vector<BoundaryCrossing>& cs) {
  std::vector<std::tuple<double, uint32_t, bool>> out;
  for (const BoundaryCrossing& c : cs) out.emplace_back(c.t, c.leaf, c.entering);
  return out;
}

using Expected = std::vector<std::tuple<double, uint32_t, bool>>;

TEST(CsgCombine, OverlappingIntervals) {
  const std::vector<std::vector<BoundaryCrossing>> ab = {intervals({0, 2}, 0), intervals({1, 3}, 1)};
  EXPECT_EQ(summary(combine_crossings(CsgOperation::Union, ab)), (Expected{{0, 0, true}, {3, 1, false}}));
  EXPECT_EQ(summary(combine_crossings(CsgOperation::Intersection, ab)), (Expected{{1, 1, true}, {2, 0, false}}));
  EXPECT_EQ(summary(combine_crossings(CsgOperation::Difference, ab)), (Expected{{0, 0, true}, {1, 1, false}}));
}

TEST(CsgCombine, TouchingOperandsMakeNoBoundaryBetweenThem) {
  const std::vector<std::vector<BoundaryCrossing>> ab = {intervals({0, 1}, 0), intervals({1, 2}, 1)};
  EXPECT_EQ(summary(combine_crossings(CsgOperation::Union, ab)), (Expected{{0, 0, true}, {2, 1, false}}));
  EXPECT_TRUE(combine_crossings(CsgOperation::Intersection, ab).empty());
  // Where both bound the solid, the first operand's surface.
  EXPECT_EQ(summary(combine_crossings(CsgOperation::Difference, ab)), (Expected{{0, 0, true}, {1, 0, false}}));
  // A tangent touch, in and out at one t, leaves the state as it was.
  const std::vector<std::vector<BoundaryCrossing>> tangent = {intervals({0, 2}, 0), intervals({1, 1}, 1)};
  EXPECT_EQ(summary(combine_crossings(CsgOperation::Union, tangent)), (Expected{{0, 0, true}, {2, 0, false}}));
  EXPECT_EQ(summary(combine_crossings(CsgOperation::Difference, tangent)), (Expected{{0, 0, true}, {2, 0, false}}));
}

TEST(CsgCombine, DifferenceOfSeveralAndAHoleInside) {
  // [0, 10] less [2, 3] and [5, 12]: inside over [0, 2] and [3, 5].
  const std::vector<std::vector<BoundaryCrossing>> ops = {intervals({0, 10}, 0), intervals({2, 3}, 1),
                                                          intervals({5, 12}, 2)};
  EXPECT_EQ(summary(combine_crossings(CsgOperation::Difference, ops)),
            (Expected{{0, 0, true}, {2, 1, false}, {3, 1, true}, {5, 2, false}}));
  // Two operands entering an intersection at once: the first one's surface.
  const std::vector<std::vector<BoundaryCrossing>> same = {intervals({1, 4}, 0), intervals({1, 3}, 1)};
  EXPECT_EQ(summary(combine_crossings(CsgOperation::Intersection, same)), (Expected{{1, 0, true}, {3, 1, false}}));
}

TEST(CsgCombine, ParsesTheOperationNames) {
  CsgOperation op;
  EXPECT_TRUE(parse_csg_operation("difference", op));
  EXPECT_EQ(op, CsgOperation::Difference);
  EXPECT_FALSE(parse_csg_operation("subtract", op));
}

// A unit tetrahedron, wound outward.
std::vector<Vec3> tetrahedron() { return {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}; }

TEST(MeshClosure, ClosedConsistentMeshesPassAndOthersSayWhy) {
  const std::vector<uint32_t> closed = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  EXPECT_EQ(mesh_closure_problem(tetrahedron(), closed), "");
  // The same corners repeated per face (as the cube stores them) are one vertex.
  std::vector<Vec3> split;
  std::vector<uint32_t> split_indices;
  for (uint32_t i : closed) {
    split_indices.push_back(uint32_t(split.size()));
    split.push_back(tetrahedron()[i]);
  }
  EXPECT_EQ(mesh_closure_problem(split, split_indices), "");
  EXPECT_THAT(mesh_closure_problem(tetrahedron(), {0, 2, 1, 0, 1, 3, 0, 3, 2}),
              HasSubstr("3 of its edges belong to one triangle only (it is not closed)"));
  EXPECT_THAT(mesh_closure_problem(tetrahedron(), {0, 1, 2, 0, 1, 3, 0, 3, 2, 1, 2, 3}),
              HasSubstr("edges join triangles wound the same way round"));
  EXPECT_THAT(mesh_closure_problem(tetrahedron(), {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3, 0, 1, 3}),
              HasSubstr("edges belong to more than two triangles"));
}

// Operands, each with an optional material (a <bsdf> element).
std::string sphere(double x, double y, double z, double r, const std::string& material = "") {
  return "<shape type='sphere'><point name='center' x='" + std::to_string(x) + "' y='" + std::to_string(y) + "' z='" +
         std::to_string(z) + "'/><float name='radius' value='" + std::to_string(r) + "'/>" + material + "</shape>";
}

std::string cube(double x, double y, double z, double half, double angle = 0, const std::string& material = "") {
  return "<shape type='cube'><transform name='to_world'><scale value='" + std::to_string(half) +
         "'/><rotate x='1' y='1' z='0' angle='" + std::to_string(angle) + "'/><translate x='" + std::to_string(x) +
         "' y='" + std::to_string(y) + "' z='" + std::to_string(z) + "'/></transform>" + material + "</shape>";
}

std::string cylinder(Vec3 p0, Vec3 p1, double r, const std::string& material = "") {
  const auto point = [](const char* name, Vec3 p) {
    return std::string("<point name='") + name + "' x='" + std::to_string(p.x) + "' y='" + std::to_string(p.y) +
           "' z='" + std::to_string(p.z) + "'/>";
  };
  return "<shape type='cylinder'>" + point("p0", p0) + point("p1", p1) + "<float name='radius' value='" +
         std::to_string(r) + "'/>" + material + "</shape>";
}

std::string csg(const std::string& op, const std::string& operands) {
  return "<shape type='csg'><string name='operation' value='" + op + "'/>" + operands + "</shape>";
}

// The solid's volume by rays along z through a jittered grid over
// [-extent, extent]^2, each walked through the scene from hit to hit,
// entering where the normal faces it and leaving where it faces away;
// a ray that enters twice or leaves twice in a row fails the test.
double volume_by_rays(const std::string& shape, float extent) {
  const auto loaded = test::scene_from_xml("<scene version='3.0.0'>" + shape + "</scene>");
  const Scene& scene = *loaded.scene;
  constexpr int n = 200;
  const double cell = 2.0 * extent / n;
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0, 1);
  double volume = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Vec3 d{0, 0, 1};
      Ray ray{{-extent + float(cell) * (float(i) + u(rng)), -extent + float(cell) * (float(j) + u(rng)), -4 * extent},
              d,
              kInfinity};
      bool inside = false;
      float entered = 0;
      for (int hits = 0; hits < 64; ++hits) {
        const auto si = scene.intersect(ray);
        if (!si) break;
        const bool entering = dot(si->ng, d) < 0;
        if (entering == inside) {
          ADD_FAILURE() << "a ray " << (entering ? "entered" : "left") << " twice at z " << si->p.z;
          return 0;
        }
        inside = entering;
        if (entering)
          entered = si->p.z;
        else
          volume += double(si->p.z - entered) * cell * cell;
        ray = si->spawn(d);
      }
      EXPECT_FALSE(inside);
    }
  return volume;
}

// Two spheres of radius r whose centres lie d apart share a lens of
// volume pi (4 r + d) (2 r - d)^2 / 12.
double lens_volume(double r, double d) { return kPi * (4 * r + d) * (2 * r - d) * (2 * r - d) / 12; }

TEST(CsgVolume, LensUnionAndDifferencesMatchTheirClosedForms) {
  const double ball = 4 * kPi / 3;
  const double lens = lens_volume(1, 1);
  EXPECT_NEAR(volume_by_rays(csg("intersection", sphere(0, 0, 0, 1) + sphere(0, 0, 1, 1)), 1.1f) / lens, 1, 3e-3);
  EXPECT_NEAR(volume_by_rays(csg("union", sphere(0, 0, 0, 1) + sphere(0, 0, 1, 1)), 1.1f) / (2 * ball - lens), 1, 3e-3);
  // A cube (half side 0.4, turned 30 degrees) hollowed out of a ball.
  EXPECT_NEAR(volume_by_rays(csg("difference", sphere(0, 0, 0, 1) + cube(0, 0, 0, 0.4, 30)), 1.1f) / (ball - 0.512), 1,
              3e-3);
  // Nested: the union of two balls less a cube at their waist, less a
  // third ball outside them (no change).
  EXPECT_NEAR(volume_by_rays(csg("difference", csg("union", sphere(0, 0, 0, 1) + sphere(0, 0, 1, 1)) +
                                                   cube(0, 0, 0.5, 0.3) + sphere(3, 0, 0, 0.5)),
                             1.1f) /
                  (2 * ball - lens - 0.216),
              1, 3e-3);
}

// A random csg tree of spheres and axis-aligned cubes inside [-0.95, 0.95]^3,
// as scene text and as the test's own point-in-solid predicate.
struct RandomSolid {
  std::string xml;
  std::function<bool(double, double, double)> inside;
};

RandomSolid random_solid(std::mt19937& rng, int depth) {
  std::uniform_real_distribution<double> u(-0.5, 0.5), size(0.15, 0.45);
  if (depth == 0 || std::uniform_int_distribution<int>(0, 3)(rng) == 0) {
    const double x = u(rng), y = u(rng), z = u(rng), r = size(rng);
    if (std::uniform_int_distribution<int>(0, 1)(rng))
      return {sphere(x, y, z, r), [=](double px, double py, double pz) {
                return (px - x) * (px - x) + (py - y) * (py - y) + (pz - z) * (pz - z) < r * r;
              }};
    return {cube(x, y, z, r), [=](double px, double py, double pz) {
              return std::abs(px - x) < r && std::abs(py - y) < r && std::abs(pz - z) < r;
            }};
  }
  const int op = std::uniform_int_distribution<int>(0, 2)(rng);
  const int count = std::uniform_int_distribution<int>(2, 3)(rng);
  std::string operands;
  std::vector<std::function<bool(double, double, double)>> parts;
  for (int i = 0; i < count; ++i) {
    RandomSolid part = random_solid(rng, depth - 1);
    operands += part.xml;
    parts.push_back(part.inside);
  }
  const char* names[] = {"union", "intersection", "difference"};
  return {csg(names[op], operands), [=](double px, double py, double pz) {
            bool any_rest = false, all = parts[0](px, py, pz);
            const bool first = all;
            for (size_t i = 1; i < parts.size(); ++i) {
              const bool in = parts[i](px, py, pz);
              any_rest = any_rest || in;
              all = all && in;
            }
            return op == 0 ? first || any_rest : op == 1 ? all : first && !any_rest;
          }};
}

// Fuzzed nesting: twenty random trees, each solid's volume cast by rays
// through the scene (which fail on any ray entering or leaving twice)
// against the fraction of 200,000 random points of [-1, 1]^3 the test's
// own predicate puts inside. The points' standard error is at most
// 8 sqrt(0.25 / 200000) = 0.0089; the bound is five of them, 0.045.
TEST(CsgVolume, RandomNestedSolidsMatchTheirPointCount) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int tree = 0; tree < 20; ++tree) {
    RandomSolid solid = random_solid(rng, 3);
    if (solid.xml.rfind("<shape type='csg'", 0) != 0) continue;
    int in = 0;
    constexpr int points = 200000;
    for (int i = 0; i < points; ++i) in += solid.inside(u(rng), u(rng), u(rng));
    const double by_points = 8.0 * in / points;
    const double by_rays = volume_by_rays(solid.xml, 1.0f);
    EXPECT_NEAR(by_rays, by_points, 0.045) << solid.xml;
  }
}

// A cylinder operand is the solid between its ends: a capsule (a cylinder
// with a ball on one end), a tilted cylinder less a thinner coaxial one
// that runs out of both ends (a tube's wall), and a cylinder whose axis
// lies along the rays (crossed only through its ends; the ball it is
// joined with lies outside the rays' reach).
TEST(CsgVolume, CylindersAreSolidsWithTheirEnds) {
  const double r = 0.4;
  EXPECT_NEAR(volume_by_rays(csg("union", cylinder({0, 0, -0.5f}, {0, 0, 0.5f}, r) + sphere(0, 0, 0.5, r)), 1.1f) /
                  (kPi * r * r + 2 * kPi * r * r * r / 3),
              1, 3e-3);
  const Vec3 p0{-0.5f, -0.3f, -0.2f}, p1{0.4f, 0.3f, 0.3f}, axis = (p1 - p0) * 0.5f;
  EXPECT_NEAR(volume_by_rays(csg("difference", cylinder(p0, p1, 0.4) + cylinder(p0 - axis, p1 + axis, 0.2)), 1.1f) /
                  (kPi * (0.16 - 0.04) * double(length(p1 - p0))),
              1, 3e-3);
  EXPECT_NEAR(
      volume_by_rays(csg("union", cylinder({0.1f, 0, -0.7f}, {0.1f, 0, 0.4f}, 0.5) + sphere(3, 3, 3, 0.1)), 1.1f) /
          (kPi * 0.25 * 1.1),
      1, 3e-3);
}

TEST(CsgShape, RefusesWhatIsNoSolidAndWhatItCannotDo) {
  const auto error = [](const std::string& shape) {
    return test::load_error("<scene version='3.0.0'>\n" + shape + "\n</scene>");
  };
  EXPECT_THAT(error(csg("xor", sphere(0, 0, 0, 1) + sphere(0, 0, 1, 1))),
              HasSubstr("must be union, intersection or difference, not 'xor'"));
  EXPECT_THAT(error(csg("union", sphere(0, 0, 0, 1))),
              HasSubstr("a csg shape needs two or more shapes inside it, not 1"));
  EXPECT_THAT(
      error(csg("union", sphere(0, 0, 0, 1) + "<shape type='disk'/>")),
      HasSubstr("a csg operand must bound a solid (a sphere, a cylinder, a cube, a closed mesh or a csg), not a disk"));
  EXPECT_THAT(error(csg("union", sphere(0, 0, 0, 1) + "<shape type='rectangle'/>")),
              HasSubstr("this rectangle does not: 4 of its edges belong to one triangle only (it is not closed)"));
  EXPECT_THAT(error("<shape type='csg'>" + sphere(0, 0, 0, 1) + sphere(0, 0, 1, 1) +
                    "<emitter type='area'><rgb name='radiance' value='1'/></emitter></shape>"),
              HasSubstr("a csg shape cannot emit"));
  EXPECT_THAT(error(csg("union", sphere(0, 0, 0, 1) +
                                     "<shape type='sphere'><emitter type='area'><rgb name='radiance' value='1'/>"
                                     "</emitter></shape>")),
              HasSubstr("test.xml:2: a csg operand cannot emit"));
  EXPECT_THAT(error("<medium type='homogeneous' id='fog'/><shape type='csg'>" + sphere(0, 0, 0, 1) +
                    sphere(0, 0, 1, 1) + "<ref name='interior' id='fog'/></shape>"),
              HasSubstr("a csg shape cannot bound media"));
}

// A glass lens made by csg, lit from above over a diffuse floor: the scene
// analysis finds the light reaching its operands' delta surfaces (hits
// name the operands), and radiosity refuses it.
TEST(CsgShape, ItsOperandsMaterialsCountInTheSceneAnalysis) {
  const std::string glass_sphere_a =
      "<shape type='sphere'><point name='center' z='0'/><bsdf type='dielectric'/></shape>";
  const std::string glass_sphere_b =
      "<shape type='sphere'><point name='center' z='1'/><bsdf type='dielectric'/></shape>";
  const std::string scene = "<scene version='3.0.0'>" + csg("intersection", glass_sphere_a + glass_sphere_b) +
                            "<shape type='rectangle'><transform name='to_world'><scale value='5'/><translate "
                            "z='-2'/></transform></shape>"
                            "<shape type='rectangle'><transform name='to_world'><rotate x='1' angle='180'/><translate "
                            "z='4'/></transform><emitter type='area'><rgb name='radiance' value='1'/></emitter></shape>"
                            "</scene>";
  const auto loaded = test::scene_from_xml(scene);
  EXPECT_TRUE(loaded.scene->features().caustic_paths) << loaded.scene->features().caustics_reason;
  EXPECT_THAT(loaded.scene->features().caustics_reason, HasSubstr("sphere"));
  const auto radiosity = test::scene_from_xml(
      "<scene version='3.0.0'><integrator type='radiosity'/>" + csg("union", sphere(0, 0, 0, 1) + sphere(0, 0, 1, 1)) +
      "<shape type='rectangle'><emitter type='area'><rgb name='radiance' value='1'/></emitter></shape></scene>");
  EXPECT_THAT(test::thrown_message<std::exception>([&] { test::render_scene(radiosity, 1); }),
              HasSubstr("is a csg solid, which it cannot mesh"));
}

// Glass solids made by csg in a white furnace (a constant environment of
// radiance 1 and nothing else): smooth glass neither absorbs nor emits,
// and a path that leaves the solid as often as it entered carries its
// weight back to exactly 1, so every pixel is 1 whatever the path. A ray
// that met the surface it left again (acne at a seam where operands meet)
// or missed a crossing would leave the solid's inside and outside
// confused and its weight off by eta^2.
TEST(CsgShape, GlassSolidsInAWhiteFurnaceStayWhite) {
  const std::string g = "<bsdf type='dielectric'/>";
  const std::string solids[] = {
      csg("intersection", sphere(0, 0, 0, 1, g) + sphere(0, 0, 1, 1, g)),
      csg("difference", sphere(0, 0, 0.5, 1, g) + cube(0.6, 0.3, 0.2, 0.5, 30, g)),
      csg("union", csg("difference", sphere(0, 0, 0, 1, g) + sphere(0, 0, 1, 0.6, g)) + cube(0, 0, -0.8, 0.4, 45, g)),
      csg("difference", cylinder({-0.2f, -0.5f, 0}, {0.3f, 0.6f, 0.5f}, 0.7, g) +
                            cylinder({-0.7f, -1.5f, -0.5f}, {0.8f, 1.6f, 1}, 0.3, g))};
  for (const std::string& solid : solids) {
    const std::string xml =
        "<scene version='3.0.0'><integrator type='path'/>"
        "<sensor type='perspective'><float name='fov' value='60'/>"
        "<transform name='to_world'><lookat origin='0.3, 0.4, -3' target='0, 0, 0.4'/></transform>"
        "<film type='hdrfilm'><integer name='width' value='32'/><integer name='height' value='32'/>"
        "<rfilter type='box'/></film></sensor>"
        "<emitter type='constant'><rgb name='radiance' value='1'/></emitter>" +
        solid + "</scene>";
    const std::vector<float> pixels = test::render_scene(test::scene_from_xml(xml), 16).resolve();
    for (size_t i = 0; i < pixels.size(); ++i) ASSERT_NEAR(pixels[i], 1, 1e-4) << solid << " pixel " << i / 3;
  }
}

// Refracts d at a surface of normal n (either side) from index n_from
// into n_to, by Snell's law.
Vec3 refract(Vec3 d, Vec3 n, float n_from, float n_to) {
  if (dot(n, d) > 0) n = -n;
  const float eta = n_from / n_to, cos_i = -dot(n, d);
  const float k = 1 - eta * eta * (1 - cos_i * cos_i);
  return normalize(d * eta + n * (eta * cos_i - std::sqrt(k)));
}

// A biconvex lens, the intersection of balls of radius R whose centres lie
// R apart (thickness R), at three scales: a ray parallel to the axis and
// near it, refracted where the scene's csg surfaces say (entering where
// the normal faces it), crosses the axis at the back focal point the
// thick-lens equation puts 0.8 R behind the back vertex for an index of
// 1.5: 1/f = (n - 1) (1/R1 - 1/R2 + (n - 1) d / (n R1 R2)) with R1 = R,
// R2 = -R, d = R gives f = 1.2 R, and the back focal distance
// f (1 - (n - 1) d / (n R1)) = 0.8 R.
TEST(CsgShape, ALensFocusesWhereTheThickLensEquationSays) {
  for (double scale : {1e-3, 1.0, 1e3}) {
    const auto loaded =
        test::scene_from_xml("<scene version='3.0.0'>" +
                             csg("intersection", sphere(0, 0, 0, scale) + sphere(0, 0, scale, scale)) + "</scene>");
    const double h = 0.01 * scale;
    Ray ray{{float(h), 0, float(-2 * scale)}, {0, 0, 1}, kInfinity};
    float index = 1;
    for (int crossing = 0; crossing < 2; ++crossing) {
      const auto si = loaded.scene->intersect(ray);
      ASSERT_TRUE(si) << "scale " << scale << " crossing " << crossing;
      const bool entering = dot(si->ng, ray.d) < 0;
      ASSERT_EQ(entering, crossing == 0) << "scale " << scale;
      const float next = entering ? 1.5f : 1.0f;
      const Vec3 d = refract(ray.d, si->ng, index, next);
      index = next;
      ray = si->spawn(d);
    }
    EXPECT_FALSE(loaded.scene->intersect(ray)) << "scale " << scale;
    const double focus = double(ray.o.z) - double(ray.o.x) / double(ray.d.x) * double(ray.d.z);
    // Paraxial at h = R / 100: spherical aberration moves it by ~1e-4 R.
    EXPECT_NEAR(focus / scale, 1.8, 1e-3) << "scale " << scale;
  }
}

// The same lens focusing in a render, by reciprocity: a camera at the
// point conjugate to a small light far away on the axis sees the light
// through the whole of the lens's middle (every pixel then shows the two
// surfaces' Fresnel transmittance, 0.9216 for an index of 1.5 near normal
// incidence: 16,384 samples of a 0/1 choice, standard error 0.002), and a
// camera 0.04 R nearer or farther sees it through part only. The light, a
// disk of radius 0.2 at 200 before the lens's front vertex, is imaged by
// Newton's equation x x' = f^2 (x measured from the front focal point at
// -0.8, x' from the back one at 1.8) at 1.8 + 1.44 / 199.2.
TEST(CsgShape, ALensRenderedSeesTheLightFromItsConjugatePoint) {
  const auto mean_seen_from = [](double z) {
    const std::string xml =
        "<scene version='3.0.0'><integrator type='path'/><sensor type='perspective'><float name='fov' value='4'/>"
        "<transform name='to_world'><lookat origin='0, 0, " +
        std::to_string(z) +
        "' target='0, 0, 0' up='0, 1, 0'/></transform><film type='hdrfilm'><integer name='width' value='16'/>"
        "<integer name='height' value='16'/><rfilter type='box'/></film></sensor>"
        "<bsdf type='dielectric' id='glass'><float name='int_ior' value='1.5'/><float name='ext_ior' value='1'/>"
        "</bsdf>" +
        csg("intersection", sphere(0, 0, 0, 1, "<ref id='glass'/>") + sphere(0, 0, 1, 1, "<ref id='glass'/>")) +
        "<shape type='disk'><transform name='to_world'><scale value='0.2'/><translate z='-200'/></transform>"
        "<emitter type='area'><rgb name='radiance' value='1'/></emitter></shape></scene>";
    const std::vector<float> pixels = test::render_scene(test::scene_from_xml(xml), 64).resolve();
    double sum = 0;
    for (float v : pixels) sum += v;
    return sum / double(pixels.size());
  };
  const double conjugate = 1.8 + 1.44 / 199.2;
  EXPECT_GT(mean_seen_from(conjugate), 0.9);
  EXPECT_LT(mean_seen_from(conjugate - 0.04), 0.75);
  EXPECT_LT(mean_seen_from(conjugate + 0.04), 0.75);
}

// The same lens focusing light, traced from the light (ptracer): a spot
// light on the axis 2 before the lens's front vertex, its beam narrowed to
// the lens's middle (radius 0.1, where spherical aberration is small), is
// imaged by Newton's equation at 1.8 + 1.44 / 1.2 = 3.0. A small diffuse
// disk (radius 0.002) facing the lens catches the beam's power there; a
// camera at a fixed place relative to the disk sees it. 0.1 nearer or
// farther, the converging cone (half-angle about 0.05) spreads the beam
// over a disk of radius about 0.005, which the receiver catches a sixth of.
// (Measured: 4.8 and 6.4 times less; the best focus lies a little nearer,
// between 2.95 and 3.0, as spherical aberration brings the outer rays in.)
TEST(CsgShape, ALensFocusesLightTracedFromTheLight) {
  const auto power_at = [](double z) {
    const std::string at = std::to_string(z), camera = std::to_string(z - 0.5);
    const std::string xml =
        "<scene version='3.0.0'><integrator type='ptracer'/><sensor type='perspective'><float name='fov' value='2'/>"
        "<transform name='to_world'><lookat origin='0.3, 0, " +
        camera + "' target='0, 0, " + at +
        "' up='0, 1, 0'/></transform><film type='hdrfilm'><integer name='width' value='16'/>"
        "<integer name='height' value='16'/><rfilter type='box'/></film></sensor>"
        "<bsdf type='dielectric' id='glass'><float name='int_ior' value='1.5'/><float name='ext_ior' value='1'/>"
        "</bsdf>" +
        csg("intersection", sphere(0, 0, 0, 1, "<ref id='glass'/>") + sphere(0, 0, 1, 1, "<ref id='glass'/>")) +
        "<emitter type='spot'><float name='cutoff_angle' value='2.86'/><float name='beam_width' value='2.86'/>"
        "<transform name='to_world'><translate z='-2'/></transform></emitter>"
        "<shape type='disk'><transform name='to_world'><scale value='0.002'/><rotate x='1' angle='180'/>"
        "<translate z='" +
        at + "'/></transform><bsdf type='diffuse'/></shape></scene>";
    const std::vector<float> pixels = test::render_scene(test::scene_from_xml(xml), 64).resolve();
    double sum = 0;
    for (float v : pixels) sum += v;
    return sum;
  };
  const double focus = power_at(3.0);
  EXPECT_GT(focus, 0);
  EXPECT_GT(focus, 3 * power_at(2.9));
  EXPECT_GT(focus, 3 * power_at(3.1));
}

// Silhouettes against images the test computes: black solids before a
// white environment, seen by an orthographic camera along -z over
// [-1.2, 1.2]^2, so each pixel shows 1 less the share of it the solid
// covers. The share is the test's own point-in-outline predicate averaged
// over 64 x 64 points of the pixel; the render's 256 samples a pixel
// estimate it with a binomial standard error, and each pixel must lie
// within five of them (plus the 64 x 64 grid's own 1/64).
TEST(CsgShape, SilhouettesMatchTheirOutlines) {
  const std::string black = "<bsdf type='diffuse'><rgb name='reflectance' value='0'/></bsdf>";
  struct Case {
    std::string solid;
    std::function<bool(double, double)> covers;
  };
  const Case cases[] = {
      // A lens whose axis lies along x: the outline of two discs' overlap.
      {csg("intersection", sphere(-0.5, 0, 0, 1, black) + sphere(0.5, 0, 0, 1, black)),
       [](double x, double y) { return (x + 0.5) * (x + 0.5) + y * y < 1 && (x - 0.5) * (x - 0.5) + y * y < 1; }},
      // A ball less the cube [0, 1]^2 x [-0.5, 0.5]: seen along z, the ball
      // is gone only where it is thinner than the cube, x^2 + y^2 > 3/4.
      {csg("difference", sphere(0, 0, 0, 1, black) + cube(0.5, 0.5, 0, 0.5, 0, black)), [](double x, double y) {
         const bool cut = x > 0 && x < 1 && y > 0 && y < 1 && x * x + y * y > 0.75;
         return x * x + y * y < 1 && !cut;
       }}};
  constexpr int kRes = 32, kSpp = 256, kGrid = 64;
  for (const Case& c : cases) {
    const std::string xml =
        "<scene version='3.0.0'><integrator type='path'/><sensor type='orthographic'>"
        "<transform name='to_world'><scale value='1.2'/><lookat origin='0, 0, 5' target='0, 0, 0' "
        "up='0, 1, 0'/></transform><film type='hdrfilm'><integer name='width' value='32'/>"
        "<integer name='height' value='32'/><rfilter type='box'/></film></sensor>"
        "<emitter type='constant'><rgb name='radiance' value='1'/></emitter>" +
        c.solid + "</scene>";
    const std::vector<float> pixels = test::render_scene(test::scene_from_xml(xml), kSpp).resolve();
    for (int py = 0; py < kRes; ++py)
      for (int px = 0; px < kRes; ++px) {
        int covered = 0;
        for (int j = 0; j < kGrid; ++j)
          for (int i = 0; i < kGrid; ++i) {
            // Image left is world -x and image top +y.
            const double x = -1.2 + 2.4 * (px + (i + 0.5) / kGrid) / kRes;
            const double y = 1.2 - 2.4 * (py + (j + 0.5) / kGrid) / kRes;
            covered += c.covers(x, y);
          }
        const double share = double(covered) / (kGrid * kGrid);
        const double error = std::sqrt(share * (1 - share) / kSpp);
        ASSERT_NEAR(1 - pixels[(size_t(py) * kRes + px) * 3], share, 5 * error + 1.0 / kGrid)
            << c.solid << " pixel " << px << ", " << py;
      }
  }
}

// The shipped scene loads and renders, every pixel finite.
TEST(CsgShape, TheShippedSceneRenders) {
  const auto loaded = load_scene(std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box-csg.xml", {{"res", "16"}});
  const std::vector<float> pixels = test::render_scene(loaded, 4).resolve();
  for (const float v : pixels) ASSERT_TRUE(std::isfinite(v));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
