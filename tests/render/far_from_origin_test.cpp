// The Cornell box moved 1e4, 1e5, 1e6 and 1e7 scene units from the origin
// along each axis renders like the box at the origin: geometry is stored
// relative to the camera, with the transforms composed in double. (Stored
// in world space, float's spacing at 1e4 is 1 mm, and the light, hung 0.1 mm
// below the ceiling, fights it; at 1e7 the image is black.)
//
// Per region of 4x4 pixels, the mean over its pixels and channels of 16
// independent runs is compared with the stored path reference of the box at
// the origin (24x24, 16384 spp), at 1% Sidak-corrected over all regions and
// offsets, against Student's t with the runs' degrees of freedom.

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "tests/support/chi2.h"
#include "tests/support/independent_runs.h"
#include "tests/support/scene_copy.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

namespace fs = std::filesystem;

constexpr int kRes = 24, kRegionsPerSide = 6, kRuns = 16, kSpp = 16;
const double kDistances[] = {1e4, 1e5, 1e6, 1e7};
constexpr int kTests = int(std::size(kDistances)) * 3 * kRegionsPerSide * kRegionsPerSide;

// The Cornell box with every to_world (the camera's too) followed by a
// translation.
fs::path moved_cornell_box(const std::string& name, double x, double y, double z) {
  char step[128];
  std::snprintf(step, sizeof step, "<translate x=\"%.17g\" y=\"%.17g\" z=\"%.17g\"/></transform>", x, y, z);
  return test::edited_cornell_box("far_" + name, [&](std::string text) {
    for (size_t at = text.find("</transform>"); at != std::string::npos; at = text.find("</transform>", at + 1)) {
      text.replace(at, 12, step);
      at += std::string(step).size() - 12;
    }
    return text;
  });
}

TEST(FarFromOrigin, TheCornellBoxRendersAsAtTheOrigin) {
  const auto regions = test::grid_regions(kRes, kRes, kRegionsPerSide);
  const auto reference = test::reference_regions("cornell-box", regions);
  const double t_critical = test::two_sided_t_critical(test::sidak_alpha(0.01, kTests), kRuns - 1);
  uint64_t seed = 1;
  for (const double d : kDistances)
    for (int axis = 0; axis < 3; ++axis) {
      const std::string name = "axis" + std::to_string(axis) + "_" + std::to_string(int(std::log10(d)));
      const fs::path file = moved_cornell_box(name, axis == 0 ? d : 0, axis == 1 ? d : 0, axis == 2 ? d : 0);
      const auto scene = load_scene(file, {{"res", std::to_string(kRes)}});
      uint64_t non_finite = 0;
      const auto estimates = test::estimate_regions(scene, regions, kSpp, kRuns, seed += kRuns, &non_finite);
      EXPECT_EQ(non_finite, 0u) << name;
      for (size_t i = 0; i < regions.size(); ++i)
        EXPECT_LT(std::abs(test::difference_score(estimates[i], reference[i])), t_critical)
            << name << " region (" << regions[i].lo.x << ", " << regions[i].lo.y << "): " << estimates[i].mean << " +- "
            << estimates[i].standard_error << ", at the origin " << reference[i].mean;
    }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
