// directionalarea (Mitsuba 3's directional area light): a flat shape facing
// down sends a parallel beam; a diffuse plane of albedo rho under it
// receives the beam's power per unit area square on, so within the beam's
// footprint it shows rho E / pi and outside it nothing. Light tracing sees
// it; every integrator that does not trace all its light from the lights
// refuses it.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "core/math/constants.h"
#include "tests/support/chi2.h"
#include "tests/support/command.h"
#include "tests/support/independent_runs.h"
#include "tests/support/test_scenes.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

constexpr double kRho = 0.6, kE = 2;

// A camera 1 above the plane looking down (16 x 16, 60 degrees: the plane
// from -0.577 to 0.577), the emitter a square of half-size `half` at height 2.
std::string beam_scene(const std::string& integrator, double half) {
  return "<scene version='3.0.0'>" + integrator +
         "<sensor type='perspective'><float name='fov' value='60'/><transform name='to_world'><lookat "
         "origin='0, 0, 1' target='0, 0, 0' up='0, 1, 0'/></transform><film type='hdrfilm'><integer name='width' "
         "value='16'/><integer name='height' value='16'/><rfilter type='box'/></film></sensor>"
         "<shape type='rectangle'><transform name='to_world'><scale value='10'/></transform><bsdf type='diffuse'>"
         "<rgb name='reflectance' value='" +
         std::to_string(kRho) + "'/></bsdf></shape><shape type='rectangle'><transform name='to_world'><scale value='" +
         std::to_string(half) +
         "'/><rotate x='1' angle='180'/><translate z='2'/></transform><emitter type='directionalarea'><rgb "
         "name='radiance' value='" +
         std::to_string(kE) + "'/></emitter></shape></scene>";
}

const std::string kPtracer = "<integrator type='ptracer'><integer name='max_depth' value='2'/></integrator>";

// A beam wider than the view lights it evenly: every region at rho E / pi,
// at 0.1 % Sidak-corrected over the regions, from independent runs.
TEST(DirectionalArea, ABeamLightsThePlaneSquareOn) {
  const auto scene = test::scene_from_xml(beam_scene(kPtracer, 3));
  const auto regions = test::grid_regions(16, 16, 4);
  constexpr int kRuns = 10;
  const double t_critical = test::two_sided_t_critical(test::sidak_alpha(0.001, int(regions.size())), kRuns - 1);
  const auto estimates = test::estimate_regions(scene, regions, 16, kRuns, 40);
  for (size_t i = 0; i < regions.size(); ++i) {
    const double score = test::difference_score(estimates[i], {kRho * kE / kPi, 0, 0});
    EXPECT_LT(std::abs(score), t_critical) << "region " << i << ": " << estimates[i].mean;
  }
}

// A beam of half-width 0.2 lights only its footprint: pixels wholly outside
// it stay exactly black (no other light reaches the plane within two
// bounces); the block of pixels wholly inside averages rho E / pi (a t-test
// at 0.1 % from independent runs).
TEST(DirectionalArea, TheBeamKeepsToItsFootprint) {
  const auto scene = test::scene_from_xml(beam_scene(kPtracer, 0.2));
  const auto image = test::render_scene(scene, 64, 3, 1).resolve();
  const size_t channels = image.size() / 256;
  const double edge = std::tan(kPi / 6), pixel = 2 * edge / 16;  // the view's half-width and a pixel's, on the plane
  test::Region inside{{16, 16}, {0, 0}};
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      const double x0 = -edge + x * pixel, y0 = -edge + y * pixel;
      if (x0 >= 0.2 || x0 + pixel <= -0.2 || y0 >= 0.2 || y0 + pixel <= -0.2) {
        EXPECT_EQ(image[(y * 16 + x) * channels], 0) << x << " " << y;
      } else if (x0 > -0.2 && x0 + pixel < 0.2 && y0 > -0.2 && y0 + pixel < 0.2) {
        inside.lo = {std::min(inside.lo.x, x), std::min(inside.lo.y, y)};
        inside.hi = {std::max(inside.hi.x, x + 1), std::max(inside.hi.y, y + 1)};
      }
    }
  ASSERT_EQ((inside.hi.x - inside.lo.x) * (inside.hi.y - inside.lo.y), 16);
  constexpr int kRuns = 10;
  const auto estimate = test::estimate_regions(scene, {inside}, 16, kRuns, 70)[0];
  EXPECT_LT(std::abs(test::difference_score(estimate, {kRho * kE / kPi, 0, 0})),
            test::two_sided_t_critical(0.001, kRuns - 1))
      << estimate.mean;
}

// Its power is radiance times area; its light paths carry it, all along the
// normal, and report no direction density to other strategies.
TEST(DirectionalArea, PowerAndLightPaths) {
  const auto scene = test::scene_from_xml(beam_scene(kPtracer, 0.5));
  const Emitter& light = *scene->emitters().front();
  EXPECT_NEAR(light.power().r, kE * 1.0, 1e-5);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0, kOneMinusEpsilon);
  double flux = 0;
  const int n = 10000;
  for (int i = 0; i < n; ++i) {
    const auto le = light.sample_Le({u(rng), u(rng)}, {u(rng), u(rng)});
    ASSERT_TRUE(le);
    EXPECT_NEAR(le->ray.d.z, -1, 1e-6);
    flux += le->Le.r / (le->pdf_pos * le->pdf_dir);
    float pdf_pos = 0, pdf_dir = 1;
    light.pdf_Le(le->ray, le->n, &pdf_pos, &pdf_dir);
    EXPECT_EQ(pdf_dir, 0);
  }
  EXPECT_NEAR(flux / n, kE * 1.0, 1e-4);
  EXPECT_FALSE(light.sample_Li({{0, 0, 0}, {}, {0, 0, 1}}, {0.5f, 0.5f}));
}

TEST(DirectionalArea, IntegratorsThatCannotSeeItRefuseByName) {
  for (const char* integrator : {"path", "bdpt", "sppm", "direct", "vcm"}) {
    const auto scene = test::scene_from_xml(beam_scene(kPtracer, 1));
    const std::string spec = integrator;
    try {
      make_integrator(spec)->check_scene(*scene);
      ADD_FAILURE() << integrator;
    } catch (const std::invalid_argument& e) {
      EXPECT_THAT(e.what(), testing::HasSubstr("integrator '" + spec + "' cannot see the directionalarea light of"))
          << integrator;
      EXPECT_THAT(e.what(), testing::HasSubstr("render it with ptracer")) << integrator;
    }
  }
  EXPECT_THAT(test::load_error("<scene version='3.0.0'>\n<emitter type='directionalarea'/></scene>"),
              testing::HasSubstr("test.xml:2: an area emitter must be nested in a shape"));
}

// caustica info says which integrators can render it.
TEST(DirectionalArea, InfoSaysWhoCanRenderIt) {
  const auto file = std::filesystem::temp_directory_path() / "caustica_directional_area.xml";
  std::ofstream(file) << beam_scene(kPtracer, 1);
  const auto r = test::run_caustica("info " + file.string());
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, testing::HasSubstr("  path: cannot render it (its directionalarea light is seen by light "
                                           "tracing only)"));
  EXPECT_THAT(r.output, testing::HasSubstr("  ptracer: "));
  EXPECT_THAT(r.output, testing::Not(testing::HasSubstr("ptracer: cannot")));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
