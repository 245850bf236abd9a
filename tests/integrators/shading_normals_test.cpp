// Shading normals that differ from the geometric ones: a floor whose every
// shading normal is tilted by 30 degrees, once by a normal map (handled
// inside the nested BSDF's frame) and once by a mesh's vertex normals
// (handled where every surface's BSDF is evaluated), lit by a rectangular
// light at an angle. Radiance and importance transport treat a shading normal
// differently (light paths need the adjoint correction |wo.ns| |wi.ng| /
// (|wo.ng| |wi.ns|)), so ptracer and bdpt agree with path region by region
// only if each handles it right. Region means over 4x4 pixels from
// independent runs, two-sample tests at 1%, Sidak-corrected over regions,
// integrators and floors, against Student's t. Fixed seeds.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "tests/support/chi2.h"
#include "tests/support/independent_runs.h"
#include "tests/support/scratch_dir.h"
#include "tests/support/test_scenes.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// A 4x4 square at z = 0 whose four vertex normals lean 30 degrees toward +x.
std::string vertex_normal_floor() {
  const auto path = test::scratch_dir() / "tilted_floor.ply";
  std::ofstream(path) << "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                         "property float z\nproperty float nx\nproperty float ny\nproperty float nz\n"
                         "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                         "-2 -2 0 0.5 0 0.8660254\n2 -2 0 0.5 0 0.8660254\n2 2 0 0.5 0 0.8660254\n"
                         "-2 2 0 0.5 0 0.8660254\n4 0 1 2 3\n";
  return "<shape type='ply'><string name='filename' value='" + path.string() +
         "'/><bsdf type='diffuse'><rgb name='reflectance' value='0.8'/></bsdf></shape>";
}

// The same tilt from a constant tangent-space normal map, 2 c - 1 = (0.5, 0, 0.866).
const char* const kNormalMapFloor =
    "<shape type='rectangle'><transform name='to_world'><scale value='2'/></transform>"
    "<bsdf type='normalmap'><rgb name='normalmap' value='0.75, 0.5, 0.933'/>"
    "<bsdf type='diffuse'><rgb name='reflectance' value='0.8'/></bsdf></bsdf></shape>";

std::string tilted_floor(const std::string& integrator, const std::string& floor) {
  return "<scene version='3.0.0'><integrator type='" + integrator +
         "'/><sensor type='perspective'><float name='fov' value='45'/>"
         "<transform name='to_world'><lookat origin='0, -3, 2.5' target='0, 0, 0' up='0, 0, 1'/></transform>"
         "<film type='hdrfilm'><integer name='width' value='24'/><integer name='height' value='24'/>"
         "<rfilter type='box'/></film></sensor>" +
         floor +
         "<shape type='rectangle'><transform name='to_world'><scale value='0.4'/><rotate x='1' angle='150'/>"
         "<translate x='-1' y='0.5' z='1.2'/></transform>"
         "<emitter type='area'><rgb name='radiance' value='10'/></emitter></shape></scene>";
}

TEST(ShadingNormals, LightTracingAndBidirectionalAgreeWithPath) {
  constexpr int kRuns = 10;
  const auto regions = test::grid_regions(24, 24, 6);
  const double t = test::two_sided_t_critical(test::sidak_alpha(0.01, 4 * int(regions.size())), kRuns - 1);
  struct Other {
    const char* name;
    uint32_t spp;
  };
  for (const std::string& floor : {std::string(kNormalMapFloor), vertex_normal_floor()}) {
    const std::string what = floor == kNormalMapFloor ? "normal map" : "vertex normals";
    const auto path = test::estimate_regions(test::scene_from_xml(tilted_floor("path", floor)), regions, 64, kRuns, 10);
    for (const Other other : {Other{"ptracer", 64}, Other{"bdpt", 16}}) {
      uint64_t non_finite = 0;
      const auto est = test::estimate_regions(test::scene_from_xml(tilted_floor(other.name, floor)), regions, other.spp,
                                              kRuns, 50, &non_finite);
      EXPECT_EQ(non_finite, 0u) << what << " " << other.name;
      int lit = 0;
      for (size_t i = 0; i < regions.size(); ++i) {
        lit += path[i].mean > 0.05;
        EXPECT_LT(std::abs(test::difference_score(est[i], path[i])), t)
            << what << " " << other.name << " region (" << regions[i].lo.x << ", " << regions[i].lo.y
            << "): " << est[i].mean << " +- " << est[i].standard_error << ", path " << path[i].mean << " +- "
            << path[i].standard_error;
      }
      EXPECT_GE(lit, 16) << what << ": at least 16 of the 36 regions should see the lit floor";
    }
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
