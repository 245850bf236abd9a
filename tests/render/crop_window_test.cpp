// A crop window renders what the whole film shows there, by camera and by
// light paths alike (the sensor's importance then covers only the window),
// and a principal point offset shifts the image by that fraction of the
// film. Per region of the window, the mean over its pixels and channels of
// 16 independent runs is compared with the stored path reference of the
// Cornell box (24x24) at the film pixels the region shows, at 1%
// Sidak-corrected over all regions, against Student's t.

#include <gtest/gtest.h>

#include <filesystem>

#include "tests/support/chi2.h"
#include "tests/support/independent_runs.h"
#include "tests/support/scene_copy.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

constexpr int kRes = 24, kRuns = 16;

struct Case {
  const char* name;
  const char* sensor;  // parameters added to the sensor
  const char* film;    // and to its film
  const char* integrator;
  uint32_t spp;
  int width, height, regions_per_side;
  Vec2i shift;  // the reference pixel a window pixel shows, less the pixel
};

const std::string kCrop =
    "<integer name='crop_offset_x' value='6'/><integer name='crop_offset_y' value='6'/>"
    "<integer name='crop_width' value='12'/><integer name='crop_height' value='12'/>";

const Case kCases[] = {{"crop_path", "", kCrop.c_str(), "path", 16, 12, 12, 3, {6, 6}},
                       {"crop_ptracer", "", kCrop.c_str(), "ptracer", 16, 12, 12, 3, {6, 6}},
                       {"principal_point",
                        "<float name='principal_point_offset_x' value='0.25'/>",
                        "<integer name='crop_width' value='18'/>",
                        "path",
                        16,
                        18,
                        24,
                        6,
                        {6, 0}}};

std::string insert_after(std::string text, const std::string& tag, const std::string& extra) {
  const size_t at = text.find(tag);
  if (at != std::string::npos) text.insert(at + tag.size(), extra);
  return text;
}

TEST(CropWindow, RendersWhatTheWholeFilmShowsThere) {
  int tests = 0;
  for (const Case& c : kCases) tests += c.regions_per_side * c.regions_per_side;
  const double t_critical = test::two_sided_t_critical(test::sidak_alpha(0.01, tests), kRuns - 1);
  uint64_t seed = 1;
  for (const Case& c : kCases) {
    const auto file = test::edited_cornell_box(std::string("crop_") + c.name, [&](std::string text) {
      return insert_after(insert_after(std::move(text), "<sensor type=\"perspective\">", c.sensor),
                          "<film type=\"hdrfilm\">", c.film);
    });
    const auto scene = load_scene(file, {{"res", std::to_string(kRes)}, {"integrator", c.integrator}});
    ASSERT_EQ(scene->sensor().film()->width(), c.width) << c.name;
    ASSERT_EQ(scene->sensor().film()->height(), c.height) << c.name;
    const auto regions = test::grid_regions(c.width, c.height, c.regions_per_side);
    std::vector<test::Region> shown;
    for (const test::Region& r : regions)
      shown.push_back({{r.lo.x + c.shift.x, r.lo.y + c.shift.y}, {r.hi.x + c.shift.x, r.hi.y + c.shift.y}});
    const auto reference = test::reference_regions("cornell-box", shown);
    const auto estimates = test::estimate_regions(scene, regions, c.spp, kRuns, seed += kRuns);
    for (size_t i = 0; i < regions.size(); ++i)
      EXPECT_LT(std::abs(test::difference_score(estimates[i], reference[i])), t_critical)
          << c.name << " region (" << regions[i].lo.x << ", " << regions[i].lo.y << "): " << estimates[i].mean << " +- "
          << estimates[i].standard_error << ", the film there " << reference[i].mean;
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
