// ptracer and bdpt through participating media, against closed forms and
// against path:
//  - a furnace: a closed emitting sphere (albedo 0.5) filled with a medium
//    of albedo 1 holds radiance 2 everywhere, light paths starting in the
//    medium the sphere bounds;
//  - the fog, smoke and subsurface boxes: per region of 6x6 pixels, ptracer's and
//    bdpt's means over its pixels and channels agree with path's.
// Both integrators' standard errors come from independent runs; each
// difference is tested at 1%, Sidak-corrected over all comparisons,
// against Student's t with the runs' degrees of freedom.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "core/loader/scene_loader.h"
#include "tests/support/chi2.h"
#include "tests/support/independent_runs.h"
#include "tests/support/test_scenes.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

constexpr int kRes = 24, kRegionsPerSide = 4, kRuns = 16;
const char* const kScenes[] = {"cornell-box-fog", "cornell-box-smoke", "cornell-box-subsurface"};
const char* const kIntegrators[] = {"ptracer", "bdpt"};
constexpr int kTests = int(std::size(kIntegrators)) * (2 + int(std::size(kScenes)) * kRegionsPerSide * kRegionsPerSide);
const double kTCritical = test::two_sided_t_critical(test::sidak_alpha(0.01, kTests), kRuns - 1);

// The camera at the centre of a closed emitting sphere of radius 1 and
// reflectance rho, the sphere (whose normals face inward, so its exterior
// is the inside) bounding the medium `medium` the camera sits in.
LoadedScene closed_sphere(const std::string& integrator, const std::string& medium, float rho) {
  return test::scene_from_xml(
      "<scene version='3.0.0'><integrator type='" + integrator + "'/>" + medium +
      "<sensor type='perspective'><float name='fov' value='70'/><ref id='m'/>"
      "<transform name='to_world'><lookat origin='0, 0, 0' target='1, 0.3, 0.2'/></transform>"
      "<film type='hdrfilm'><integer name='width' value='8'/><integer name='height' value='8'/>"
      "<rfilter type='box'/></film></sensor>"
      "<shape type='sphere'><boolean name='flip_normals' value='true'/><ref name='exterior' id='m'/>"
      "<bsdf type='diffuse'><rgb name='reflectance' value='" +
      std::to_string(rho) +
      "'/></bsdf><emitter type='area'><rgb name='radiance' value='1'/></emitter></shape></scene>");
}

void expect_image_mean(const LoadedScene& scene, double expected) {
  uint64_t non_finite = 0;
  const auto estimate = test::estimate_regions(scene, {{{0, 0}, {8, 8}}}, 16, kRuns, 1, &non_finite)[0];
  EXPECT_EQ(non_finite, 0u);
  EXPECT_LT(std::abs(estimate.mean - expected) / estimate.standard_error, kTCritical)
      << estimate.mean << " +- " << estimate.standard_error << ", expected " << expected;
}

class MediumAgreement : public testing::TestWithParam<const char*> {};

TEST_P(MediumAgreement, FurnaceHoldsTwo) {
  expect_image_mean(closed_sphere(GetParam(),
                                  "<medium type='homogeneous' id='m'><rgb name='sigma_t' value='0.5, 1, 3'/>"
                                  "<float name='albedo' value='1'/><phase type='hg'><float name='g' value='0.5'/>"
                                  "</phase></medium>",
                                  0.5f),
                    2);
}

TEST_P(MediumAgreement, LightStartsInTheMediumItsShapeBounds) {
  // Absorption alone, a black sphere: the centre sees exp(-sigma_t) per
  // channel, which only the light's own medium can give joined light vertices.
  expect_image_mean(closed_sphere(GetParam(),
                                  "<medium type='homogeneous' id='m'><rgb name='sigma_t' value='0.5, 1, 3'/>"
                                  "<float name='albedo' value='0'/></medium>",
                                  0),
                    (std::exp(-0.5) + std::exp(-1.0) + std::exp(-3.0)) / 3);
}

INSTANTIATE_TEST_SUITE_P(Integrators, MediumAgreement, testing::ValuesIn(kIntegrators), test::scene_test_name);

// Each integrator against path, on each box.
class BoxAgreement : public testing::TestWithParam<std::tuple<const char*, const char*>> {};

TEST_P(BoxAgreement, RegionsMatchPath) {
  const auto [integrator, name] = GetParam();
  const auto regions = test::grid_regions(kRes, kRes, kRegionsPerSide);
  const auto load = [&](const char* which) {
    return load_scene(std::string(CAUSTICA_SOURCE_DIR) + "/scenes/" + name + ".xml",
                      {{"res", std::to_string(kRes)}, {"integrator", which}});
  };
  uint64_t non_finite = 0;
  const auto path = test::estimate_regions(load("path"), regions, 16, kRuns, 100, &non_finite);
  const bool light_tracing = std::string(integrator) == "ptracer";
  const auto other = test::estimate_regions(load(integrator), regions, light_tracing ? 32 : 8, kRuns, 200, &non_finite);
  EXPECT_EQ(non_finite, 0u);
  for (size_t i = 0; i < regions.size(); ++i)
    EXPECT_LT(std::abs(test::difference_score(other[i], path[i])), kTCritical)
        << name << " region (" << regions[i].lo.x << ", " << regions[i].lo.y << "): " << integrator << " "
        << other[i].mean << " +- " << other[i].standard_error << ", path " << path[i].mean << " +- "
        << path[i].standard_error;
}

INSTANTIATE_TEST_SUITE_P(Boxes, BoxAgreement,
                         testing::Combine(testing::ValuesIn(kIntegrators), testing::ValuesIn(kScenes)),
                         [](const auto& info) {
                           std::string name = std::get<0>(info.param) + std::string("_") + std::get<1>(info.param);
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
