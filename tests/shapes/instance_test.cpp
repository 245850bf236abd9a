// shapegroup and instance: a scene placing a group by instances hits
// exactly what the same scene written out shape by shape hits (each shape's
// to_world composed by hand with its instance's), whatever the instance's
// rotation, scale or distance from the origin; rays leaving instance hits
// never find their own surface again; and bad nesting is refused by name.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <random>

#include "core/bsdf/bsdf.h"
#include "core/math/constants.h"
#include "core/registry/properties.h"
#include "core/sampling/warp.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using testing::HasSubstr;

// The group's shapes, each with its own placement inside the group.
const char* kCubeInGroup =
    "<transform name='to_world'><scale x='0.5' y='0.2' z='0.3'/><rotate z='1' angle='20'/></transform>";
const char* kSphereInGroup = "<point name='center' x='1' y='0' z='0'/><float name='radius' value='0.4'/>";
const char* kDiskInGroup = "<transform name='to_world'><rotate x='1' angle='70'/><translate y='-1'/></transform>";

// Placements of the group: rigid, uniformly scaled, mirrored, far away.
const char* kPlacements[] = {
    "<rotate y='1' angle='35'/><translate x='0.5' y='0.3' z='-0.2'/>",
    "<scale value='1.7'/><rotate x='1' y='1' angle='-60'/><translate x='-2' z='1'/>",
    "<scale x='-1'/><translate y='2'/>",
    "<translate x='10000' y='-20000' z='5000'/>",
};

std::string grouped_scene(const std::string& sensor) {
  std::string xml = "<scene version='3.0.0'>" + sensor +
                    "<shape type='shapegroup' id='g'>"
                    "<shape type='cube'>" +
                    std::string(kCubeInGroup) +
                    "<bsdf type='conductor'/></shape>"
                    "<shape type='sphere'>" +
                    kSphereInGroup +
                    "</shape>"
                    "<shape type='disk'>" +
                    kDiskInGroup + "</shape></shape>";
  for (const char* placement : kPlacements)
    xml += "<shape type='instance'><ref id='g'/><transform name='to_world'>" + std::string(placement) +
           "</transform></shape>";
  return xml + "</scene>";
}

// The same shapes written out: the sphere's centre and radius become a
// transform of the unit sphere so the placement composes with it.
std::string explicit_scene(const std::string& sensor) {
  std::string xml = "<scene version='3.0.0'>" + sensor;
  for (const char* placement : kPlacements) {
    const std::string p(placement);
    xml += "<shape type='cube'><transform name='to_world'><scale x='0.5' y='0.2' z='0.3'/><rotate z='1' angle='20'/>" +
           p + "</transform><bsdf type='conductor'/></shape>";
    xml += "<shape type='sphere'><transform name='to_world'><scale value='0.4'/><translate x='1'/>" + p +
           "</transform></shape>";
    xml += "<shape type='disk'><transform name='to_world'><rotate x='1' angle='70'/><translate y='-1'/>" + p +
           "</transform></shape>";
  }
  return xml + "</scene>";
}

// Rays toward each placement's neighbourhood, from random points around it.
std::vector<Ray> probe_rays(const Scene& scene, int n) {
  std::mt19937 rng(8);
  std::uniform_real_distribution<float> u(0, kOneMinusEpsilon);
  const Vec3d targets[] = {{0.5, 0.3, -0.2}, {-2, 0, 1}, {0, 2, 0}, {10000, -20000, 5000}};
  std::vector<Ray> rays;
  for (int i = 0; i < n; ++i) {
    const Vec3 target = scene.render_point(targets[i % 4]) + square_to_uniform_sphere({u(rng), u(rng)}) * u(rng);
    const Vec3 o = target + square_to_uniform_sphere({u(rng), u(rng)}) * 4.0f;
    rays.push_back({o, normalize(target - o)});
  }
  return rays;
}

// Render space starts at the camera: at the origin, and away from it
// (where the group's shapes must stay in the group's space and only the
// instances move).
const char* kSensor = "<sensor type='perspective'/>";
const char* kSensorAway =
    "<sensor type='perspective'><transform name='to_world'><lookat origin='3, 1, 5' target='0, 0, 0' up='0, 1, 0'/>"
    "</transform></sensor>";

class Instance : public testing::TestWithParam<const char*> {};

TEST_P(Instance, HitsWhatTheShapesWrittenOutHit) {
  const auto grouped = test::scene_from_xml(grouped_scene(GetParam()));
  const auto written = test::scene_from_xml(explicit_scene(GetParam()));
  EXPECT_EQ(grouped->shapes().size(), 4u);  // the group itself is not drawn
  int hits = 0, edge_hits = 0;
  for (const Ray& ray : probe_rays(*grouped, 4000)) {
    const auto a = grouped->intersect(ray), b = written->intersect(ray);
    ASSERT_EQ(a.has_value(), b.has_value()) << ray.o.x << " " << ray.o.y << " " << ray.o.z;
    if (!a) continue;
    ++hits;
    const float scale = std::max(1.0f, max_component(abs(b->p)));
    // Far from the origin both are as exact as float's spacing there allows.
    EXPECT_NEAR(a->t, b->t, 2e-4f * std::max(1.0f, b->t) + 4 * scale * 0x1p-23f);
    EXPECT_NEAR(length(a->p - b->p), 0, 1e-4f * scale);
    // Normals agree up to their side: a mesh written out under a mirror
    // takes its side from its winding, which the mirror reverses, while an
    // instance keeps the group's outside out (see AMirrorKeepsTheOutsideOut).
    // At a cube's edge, where the points agree, either face may be reported.
    if (std::abs(dot(a->ng, b->ng)) < 1 - 1e-4f) {
      ++edge_hits;
      continue;
    }
    EXPECT_GT(std::abs(dot(a->shading.n, b->shading.n)), 1 - 1e-4f);
    EXPECT_GT(dot(a->ng, a->shading.n), 0);
    EXPECT_EQ(a->shape->kind(), b->shape->kind());
    EXPECT_EQ(a->shape->bsdf()->plugin_name(), b->shape->bsdf()->plugin_name());
  }
  EXPECT_LE(edge_hits, hits / 100);
  EXPECT_GT(hits, 1500);
}

INSTANTIATE_TEST_SUITE_P(Cameras, Instance, testing::Values(kSensor, kSensorAway));

// Rays spawned from instance hits away from the surface never meet it
// again (the group's shapes are convex, and the nearest other surface is
// more than 0.05 away), even 20000 units from the origin.
TEST(Instance, RaysLeavingAHitDoNotFindItAgain) {
  const auto grouped = test::scene_from_xml(grouped_scene(kSensor));
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> u(0, kOneMinusEpsilon);
  int spawned = 0;
  for (const Ray& ray : probe_rays(*grouped, 4000)) {
    const auto si = grouped->intersect(ray);
    if (!si) continue;
    Vec3 d = square_to_uniform_sphere({u(rng), u(rng)});
    if (dot(d, si->ng) < 0) d = -d;
    const auto again = grouped->intersect(si->spawn(d));
    ++spawned;
    if (again) {
      EXPECT_GT(again->t, 0.05f) << si->shape->kind() << " at " << si->p.x << " " << si->p.y << " " << si->p.z;
    }
  }
  EXPECT_GT(spawned, 1500);
}

// A non-uniform scale tilts normals differently from the surface's
// tangents: the instance's normals still match the mesh written out.
TEST(Instance, NonUniformScaleKeepsNormalsPerpendicular) {
  const std::string placement =
      "<rotate z='1' angle='30'/><scale x='3' y='0.5' z='1.5'/><rotate x='1' y='1' angle='40'/>";
  const auto grouped = test::scene_from_xml(
      "<scene version='3.0.0'><shape type='shapegroup' id='g'><shape type='cube'/></shape><shape type='instance'>"
      "<ref id='g'/><transform name='to_world'>" +
      placement + "</transform></shape></scene>");
  const auto written = test::scene_from_xml("<scene version='3.0.0'><shape type='cube'><transform name='to_world'>" +
                                            placement + "</transform></shape></scene>");
  int hits = 0;
  for (const Ray& ray : probe_rays(*grouped, 400)) {
    if (!(length(ray.o) < 10)) continue;  // the probes around the origin
    const auto a = grouped->intersect(ray), b = written->intersect(ray);
    ASSERT_EQ(a.has_value(), b.has_value());
    if (!a || std::abs(dot(a->ng, b->ng)) < 0.5f) continue;  // either face at an edge
    ++hits;
    EXPECT_GT(dot(a->ng, b->ng), 1 - 1e-4f);
  }
  EXPECT_GT(hits, 50);
}

// A mirrored instance of a closed mesh still faces outward: its normals are
// the group's carried by the inverse transpose, which keeps sides.
TEST(Instance, AMirrorKeepsTheOutsideOut) {
  const auto scene = test::scene_from_xml(
      "<scene version='3.0.0'><shape type='shapegroup' id='g'><shape type='cube'/></shape>"
      "<shape type='instance'><ref id='g'/><transform name='to_world'><scale x='-1'/></transform></shape></scene>");
  for (const Vec3 d : {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, -1)}) {
    const auto si = scene->intersect({d * -5.0f, d});
    ASSERT_TRUE(si);
    EXPECT_NEAR(dot(si->ng, -d), 1, 1e-6f);
  }
}

// An instance's area samples are its group's moved into place, with the
// density per unit area of the placed surface: over a uniform scale s the
// density falls by s^2.
TEST(Instance, PositionSamplesFollowTheScaledArea) {
  const auto scene = test::scene_from_xml(
      "<scene version='3.0.0'><shape type='shapegroup' id='g'><shape type='rectangle'/></shape>"
      "<shape type='instance'><ref id='g'/><transform name='to_world'><scale x='3' y='-3' z='3'/>"
      "<translate z='2'/></transform></shape></scene>");
  const Shape& instance = *scene->shapes().front();
  EXPECT_EQ(instance.kind(), "instance");
  const PositionSample ps = instance.sample_position({0.3f, 0.8f});
  EXPECT_NEAR(ps.pdf, 1.0f / 36, 1e-6f);  // the rectangle [-1, 1]^2 becomes 6 x 6
  EXPECT_NEAR(ps.p.z, 2, 1e-5f);
  EXPECT_NEAR(std::abs(ps.n.z), 1, 1e-6f);
}

// What the scene analysis sees through an instance: its group's materials.
TEST(Instance, SceneFeaturesSeeTheGroupsMaterials) {
  const auto scene = test::scene_from_xml(
      "<scene version='3.0.0'><shape type='shapegroup' id='g'><shape type='sphere'><bsdf type='dielectric'/>"
      "</shape></shape><shape type='instance'><ref id='g'/></shape>"
      "<shape type='rectangle'><transform name='to_world'><translate z='-2'/><scale value='5'/></transform>"
      "</shape><emitter type='point'><point name='position' x='0' y='0' z='3'/></emitter></scene>");
  EXPECT_TRUE(scene->features().lobes & kDeltaTransmission);
  EXPECT_TRUE(scene->features().caustic_paths) << scene->features().caustics_reason;
}

TEST(Instance, BadNestingIsRefusedByName) {
  const std::string group = "<shape type='shapegroup' id='g'><shape type='sphere'/></shape>";
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><shape type='instance'/></scene>"),
              HasSubstr("an instance takes exactly one shapegroup"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><shape type='sphere' id='s'/><shape type='instance'>"
                               "<ref id='s'/></shape></scene>"),
              HasSubstr("an instance takes exactly one shapegroup"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><shape type='shapegroup' id='g'/></scene>"),
              HasSubstr("a shapegroup needs at least one shape"));
  EXPECT_THAT(
      test::load_error("<scene version='3.0.0'><shape type='shapegroup' id='g'><shape type='sphere'>"
                       "<emitter type='area'><rgb name='radiance' value='1'/></emitter></shape></shape></scene>"),
      HasSubstr("a shapegroup's shapes cannot emit"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'>" + group +
                               "<shape type='instance'><ref id='g'/><emitter type='area'><rgb name='radiance' "
                               "value='1'/></emitter></shape></scene>"),
              HasSubstr("shape 'instance' does not take a nested <emitter>"));
  // A shape drawn both in a group's space and in the scene's.
  EXPECT_THAT(test::load_error("<scene version='3.0.0'><shape type='sphere' id='s'/><shape type='shapegroup' "
                               "id='g'><ref id='s'/></shape></scene>"),
              HasSubstr("shape 's' is used both inside a shapegroup and outside one"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'>" + group +
                               "<shape type='shapegroup' id='h'><shape type='instance'><ref id='g'/></shape></shape>"
                               "</scene>"),
              HasSubstr("one level of instancing"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
