// The radiosity integrator as an oracle: a closed diffuse enclosure that
// emits everywhere has L = E / (1 - rho) exactly (each element's form
// factors sum to one there), for a meshed cube and a tessellated sphere; on
// the Cornell box its region means approach the stored path reference
// (tests/data/references, 16384 spp) as the elements shrink; the image is
// the same for any thread count; and what it cannot render is refused.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/independent_runs.h"
#include "tests/support/test_scenes.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using testing::HasSubstr;

std::string enclosure(const std::string& shape, const std::string& integrator) {
  return "<scene version='3.0.0'>" + integrator +
         "<sensor type='perspective'><float name='fov' value='70'/><sampler type='independent'/>"
         "<transform name='to_world'><lookat origin='0.1, 0.2, 0' target='1, 0.3, 0.2'/></transform>"
         "<film type='hdrfilm'><integer name='width' value='16'/><integer name='height' value='16'/>"
         "<rfilter type='box'/></film></sensor>"
         "<shape type='" +
         shape +
         "'><boolean name='flip_normals' value='true'/>"
         "<bsdf type='diffuse'><rgb name='reflectance' value='0.5'/></bsdf>"
         "<emitter type='area'><rgb name='radiance' value='1'/></emitter></shape></scene>";
}

TEST(RadiosityEnclosure, EmittingDiffuseBoxAndSphereReachEOverOneMinusRho) {
  for (const char* shape : {"cube", "sphere"}) {
    const auto scene = test::scene_from_xml(
        enclosure(shape, "<integrator type='radiosity'><float name='patch_size' value='0.4'/></integrator>"));
    const std::vector<float> pixels = test::render_scene(scene, 1).resolve();
    for (const float v : pixels) ASSERT_NEAR(v, 2.0f, 2e-3f) << shape;
  }
}

TEST(RadiosityEnclosure, FinalGatheringSeesTheSameValue) {
  const auto scene = test::scene_from_xml(
      enclosure("cube",
                "<integrator type='radiosity'><float name='patch_size' value='0.5'/><integer name='gather' value='4'/>"
                "</integrator>"));
  for (const float v : test::render_scene(scene, 2).resolve()) ASSERT_NEAR(v, 2.0f, 2e-3f);
}

// Mean relative difference of the region means from the path reference.
double difference_from_reference(const std::string& scene, const std::string& spec) {
  constexpr int kRes = 24, kRegionsPerSide = 6;
  const auto regions = test::grid_regions(kRes, kRes, kRegionsPerSide);
  const auto estimate = test::estimate_regions(test::scene_with_integrator(scene, spec, kRes), regions, 16, 1, 1);
  const auto reference = test::reference_regions(scene, regions);
  double sum = 0;
  for (size_t i = 0; i < regions.size(); ++i) sum += std::abs(estimate[i].mean - reference[i].mean) / reference[i].mean;
  return sum / double(regions.size());
}

// The diffuse Cornell scenes with stored path references: the plain box
// and the textured floor (its checkerboard averaged per element, its bump
// map seen only by the path reference).
TEST(RadiosityCornellBox, ApproachesThePathReferenceAsElementsShrink) {
  for (const char* scene : {"cornell-box", "cornell-box-textured"}) {
    const double coarse = difference_from_reference(scene, "radiosity:patch_size=0.3,refinements=0");
    const double medium = difference_from_reference(scene, "radiosity:patch_size=0.15,refinements=0");
    const double fine = difference_from_reference(scene, "radiosity:patch_size=0.075,refinements=0");
    EXPECT_LT(medium, coarse) << scene;
    EXPECT_LT(fine, medium) << scene;
    const double adaptive = difference_from_reference(scene, "radiosity:patch_size=0.15,refinements=2");
    EXPECT_LT(adaptive, medium) << scene;
    EXPECT_LT(fine, 0.05) << scene;
    std::printf("%s: mean relative difference from path: %.4f %.4f %.4f, adaptive %.4f\n", scene, coarse, medium, fine,
                adaptive);
  }
}

TEST(Radiosity, SameImageForAnyThreadCount) {
  const auto scene = test::scene_with_integrator("cornell-box", "radiosity:patch_size=0.2,gather=2", 16);
  EXPECT_EQ(test::render_scene(scene, 4, 3, 1).resolve(), test::render_scene(scene, 4, 3, 2).resolve());
}

std::string render_error(const std::string& scene_name, const std::string& spec) {
  try {
    test::render_scene(test::scene_with_integrator(scene_name, spec, 8), 1);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(Radiosity, RefusesWhatItCannotRender) {
  EXPECT_THAT(render_error("cornell-box-glossy", "radiosity"),
              testing::AllOf(HasSubstr("integrator 'radiosity' renders only diffuse surfaces lit by area emitters"),
                             HasSubstr("which is not diffuse"), HasSubstr("render"), HasSubstr("with path")));
  const std::string point_light =
      "<scene version='3.0.0'><integrator type='radiosity'/><sensor type='perspective'><film type='hdrfilm'>"
      "<integer name='width' value='4'/><integer name='height' value='4'/></film></sensor>"
      "<emitter type='point'><point name='position' x='0' y='0' z='1'/></emitter>"
      "<shape type='rectangle'><bsdf type='diffuse'/></shape></scene>";
  try {
    test::render_scene(test::scene_from_xml(point_light), 1);
    ADD_FAILURE() << "a point light was rendered";
  } catch (const std::exception& e) {
    EXPECT_THAT(e.what(), HasSubstr("the emitter 'point' is not one"));
  }
}

TEST(Radiosity, RejectsBadParameters) {
  const auto error = [](const std::string& params) {
    return test::load_error("<scene version='3.0.0'><integrator type='radiosity'>" + params + "</integrator></scene>");
  };
  EXPECT_THAT(error("<integer name='max_depth' value='5'/>"), HasSubstr("must be -1"));
  EXPECT_EQ(error("<integer name='max_depth' value='-1'/>"), "");
  EXPECT_THAT(error("<float name='patch_size' value='-1'/>"), HasSubstr("patch_size"));
  EXPECT_THAT(error("<float name='patch_size' value='-1'/>"), HasSubstr("must be positive"));
  EXPECT_THAT(error("<integer name='refinements' value='9'/>"), HasSubstr("must be between 0 and 8"));
  EXPECT_THAT(error("<float name='refine_threshold' value='0'/>"), HasSubstr("refine_threshold"));
  EXPECT_THAT(error("<integer name='visibility_rays' value='0'/>"), HasSubstr("must be between 1 and 16"));
  EXPECT_THAT(error("<float name='tolerance' value='1'/>"), HasSubstr("must be in (0, 1)"));
  EXPECT_THAT(error("<integer name='gather' value='-1'/>"), HasSubstr("must be between 0 and 4096"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
