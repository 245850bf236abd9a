// `caustica merge` and `caustica compare` end to end, on renders of a tiny
// Cornell box: what the reference and convergence benchmarks run.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

#include "core/image/image_input.h"
#include "tests/support/command.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using testing::HasSubstr;

using test::run_caustica;

class MergeAndCompare : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    std::filesystem::create_directories(dir());
    for (int seed : {1, 2, 3}) {
      const test::CommandResult r =
          run_caustica("render " + std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box.xml -o " + chunk(seed) +
                       " --spp 4 -D res=8 --threads 2 -q --exr-format float --seed " + std::to_string(seed));
      ASSERT_EQ(r.status, 0) << r.output;
    }
  }
  static std::filesystem::path dir() { return std::filesystem::temp_directory_path() / "caustica_merge_test"; }
  static std::string chunk(int seed) { return (dir() / ("chunk" + std::to_string(seed) + ".exr")).string(); }

  // compare's "name value" lines.
  static std::map<std::string, double> metrics(const std::string& output) {
    std::map<std::string, double> out;
    std::istringstream in(output);
    std::string name;
    double value;
    while (in >> name >> value) out[name] = value;
    return out;
  }
};

TEST_F(MergeAndCompare, MergeAddsSamplesAndStoresTheEstimatedError) {
  const std::string merged = (dir() / "merged.exr").string();
  const test::CommandResult r = run_caustica("merge " + chunk(1) + " " + chunk(2) + " -o " + merged);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("2 renders, 8 spp -> " + merged + ", estimated MSE "));
  std::map<std::string, std::string> metadata;
  const Image image = read_image(merged, &metadata);
  EXPECT_EQ(metadata["caustica:spp"], "8");
  EXPECT_EQ(metadata["caustica:seeds"], "1,2");
  EXPECT_EQ(metadata["caustica:samples"], std::to_string(8 * 8 * 8));
  EXPECT_GT(std::stod(metadata["caustica:estimated_mse"]), 0);
  EXPECT_GT(std::stod(metadata["caustica:estimated_rel_mse"]), 0);
  EXPECT_EQ(image.pixels[image.channel_index("samples.Y")], 8);
}

TEST_F(MergeAndCompare, CompareDiscountsTheReferenceNoise) {
  const std::string reference = (dir() / "reference.exr").string();
  ASSERT_EQ(run_caustica("merge " + chunk(2) + " " + chunk(3) + " -o " + reference).status, 0);
  const test::CommandResult r = run_caustica("compare " + chunk(1) + " " + reference);
  ASSERT_EQ(r.status, 0) << r.output;
  const auto m = metrics(r.output);
  for (const char* name : {"mse", "mse_corrected", "rel_mse", "rel_mse_corrected", "mae", "reference_estimated_mse",
                           "reference_estimated_rel_mse", "estimated_mse", "estimated_rel_mse"})
    EXPECT_EQ(m.count(name), 1u) << name << " in\n" << r.output;
  EXPECT_GT(m.at("mse"), 0);
  EXPECT_NEAR(m.at("mse_corrected"), m.at("mse") - m.at("reference_estimated_mse"), 1e-6 * m.at("mse"));
  EXPECT_THAT(r.output, testing::Not(HasSubstr("warning")));
}

TEST_F(MergeAndCompare, SharedSeedsAreCaught) {
  const std::string reference = (dir() / "reference12.exr").string();
  ASSERT_EQ(run_caustica("merge " + chunk(1) + " " + chunk(2) + " -o " + reference).status, 0);
  EXPECT_THAT(run_caustica("compare " + chunk(1) + " " + reference).output,
              HasSubstr("share seed 1: their errors are correlated"));
  const test::CommandResult twice =
      run_caustica("merge " + chunk(1) + " " + chunk(1) + " -o " + (dir() / "x.exr").string());
  EXPECT_EQ(twice.status, 1);
  EXPECT_THAT(twice.output, HasSubstr("were both rendered with seed 1"));
}

TEST_F(MergeAndCompare, CompareRejectsImagesOfAnotherSize) {
  const std::string big = (dir() / "big.exr").string();
  ASSERT_EQ(run_caustica("render " + std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box.xml -o " + big +
                         " --spp 1 -D res=9 -q")
                .status,
            0);
  const test::CommandResult r = run_caustica("compare " + big + " " + chunk(1));
  EXPECT_EQ(r.status, 1);
  EXPECT_THAT(r.output, HasSubstr("caustica: error: the image is 9x9 but the reference is 8x8"));
}

// A display PNG holds tone-mapped, screen-encoded values: its error against
// a linear reference would mean nothing, so compare refuses it, either way
// round.
TEST_F(MergeAndCompare, CompareRefusesDisplayImages) {
  const std::string exr = (dir() / "display.exr").string(), png = (dir() / "display.png").string();
  ASSERT_EQ(run_caustica("render " + std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box.xml -o " + exr +
                         " --spp 1 -D res=8 -q")
                .status,
            0);
  for (const std::string& args : {png + " " + exr, exr + " " + png}) {
    const test::CommandResult r = run_caustica("compare " + args);
    EXPECT_EQ(r.status, 1) << args;
    EXPECT_THAT(r.output, HasSubstr("caustica: error: '" + png +
                                    "' is a display image (tone-mapped and encoded for a screen); errors are measured "
                                    "on linear renders (.exr, .hdr, .pfm)"))
        << args;
  }
}

// Two renders of one seed over disjoint --first-sample ranges, merged from
// their raw sums, are the one render of all their samples, pixel for pixel.
TEST_F(MergeAndCompare, RangesOfOneSeedMergeIntoTheRenderOfTheirUnion) {
  const std::string scene = std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box.xml";
  const auto render = [&](const std::string& name, const std::string& range) {
    const std::string out = (dir() / name).string();
    const test::CommandResult r =
        run_caustica("render " + scene + " -o " + out + " -D res=8 --threads 2 -q --seed 5 --raw-sums " + range);
    EXPECT_EQ(r.status, 0) << r.output;
    return out;
  };
  const std::string whole = render("whole.exr", "--spp 7");
  const std::string first = render("first.exr", "--spp 3"), rest = render("rest.exr", "--first-sample 3 --spp 4");
  const std::string merged = (dir() / "ranges.exr").string();
  const test::CommandResult r = run_caustica("merge " + rest + " " + first + " -o " + merged);
  ASSERT_EQ(r.status, 0) << r.output;
  std::map<std::string, std::string> merged_meta, whole_meta;
  const Image a = read_image(merged, &merged_meta), b = read_image(whole, &whole_meta);
  ASSERT_EQ(a.channels, b.channels);
  // The images; the raw sums themselves may differ in their last bits, as
  // their doubles were added in another order.
  size_t compared = 0;
  for (size_t c = 0; c < a.channels.size(); ++c) {
    if (a.channels[c].rfind("raw.", 0) == 0) continue;
    ++compared;
    for (size_t i = c; i < a.pixels.size(); i += a.channels.size())
      ASSERT_EQ(a.pixels[i], b.pixels[i]) << a.channels[c] << " of pixel " << i / a.channels.size();
  }
  EXPECT_EQ(compared, 14u);  // R, G, B, albedo.*, normal.*, depth.T, variance.*, samples.Y
  EXPECT_EQ(merged_meta["caustica:ranges"], "0-6");
  EXPECT_EQ(merged_meta["caustica:spp"], "7");
  EXPECT_EQ(whole_meta["caustica:first_sample"], "0");
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
