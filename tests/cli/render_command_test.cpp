// The caustica executable end to end: what a user types and sees.

#include <OpenImageIO/imageio.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace caustica {
namespace {

using testing::HasSubstr;

struct CommandResult {
  int status;
  std::string output;  // stdout and stderr together
};

CommandResult run(const std::string& args) {
  const std::string cmd = std::string(CAUSTICA_BINARY) + " " + args + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  std::string out;
  std::array<char, 4096> buf;
  while (size_t n = fread(buf.data(), 1, buf.size(), pipe)) out.append(buf.data(), n);
  const int status = pclose(pipe);
  return {WEXITSTATUS(status), out};
}

std::filesystem::path temp_dir() {
  const auto dir = std::filesystem::temp_directory_path() / "caustica_cli_test";
  std::filesystem::create_directories(dir);
  return dir;
}

const std::string kCornell = std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box.xml";

TEST(RenderCommand, WritesExrAndPngAndASummary) {
  const auto exr = temp_dir() / "box.exr";
  std::filesystem::remove(exr);
  const CommandResult r = run("render " + kCornell + " -o " + exr.string() + " --spp 2 -D res=24 --threads 2 --seed 3");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("24x24, 2 spp in"));
  EXPECT_THAT(r.output, HasSubstr("M rays/s"));
  EXPECT_THAT(r.output, HasSubstr("0 non-finite samples dropped"));

  auto in = OIIO::ImageInput::open(exr.string());
  ASSERT_TRUE(in);
  const OIIO::ImageSpec& spec = in->spec();
  EXPECT_EQ(spec.width, 24);
  EXPECT_EQ(spec.nchannels, 3);
  EXPECT_EQ(spec.get_string_attribute("caustica:spp"), "2");
  EXPECT_EQ(spec.get_string_attribute("caustica:seed"), "3");
  std::vector<float> pixels(24 * 24 * 3);
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, pixels.data()));
  double sum = 0;
  for (float v : pixels) {
    EXPECT_TRUE(std::isfinite(v));
    sum += v;
  }
  EXPECT_GT(sum, 0);
  auto png = OIIO::ImageInput::open((temp_dir() / "box.png").string());
  ASSERT_TRUE(png);
  EXPECT_EQ(png->spec().format, OIIO::TypeDesc::UINT8);
}

TEST(RenderCommand, DebugPixelReplaysOneSample) {
  const CommandResult r = run("render " + kCornell + " -D res=24 --debug-pixel 12,12 --debug-sample 3");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("R = "));
  EXPECT_EQ(r.output, run("render " + kCornell + " -D res=24 --debug-pixel 12,12 --debug-sample 3").output);
}

TEST(RenderCommand, IntegratorOverrideAndInfo) {
  const auto exr = temp_dir() / "aov.exr";
  const CommandResult r = run("render " + kCornell + " -o " + exr.string() + " --spp 1 -D res=8 --integrator aov -q");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output, "");
  auto in = OIIO::ImageInput::open(exr.string());
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().channelnames[0], "albedo.R");
  const CommandResult info = run("info " + kCornell);
  EXPECT_THAT(info.output, HasSubstr("emitters: 1 (area: 1"));
}

TEST(RenderCommand, ErrorsNameTheProblem) {
  EXPECT_THAT(run("render " + kCornell + " --integrator nope").output,
              HasSubstr("caustica: error: unknown integrator 'nope'"));
  EXPECT_THAT(run("render " + kCornell + " -D spp").output, HasSubstr("-D expects name=value, got 'spp'"));
  EXPECT_THAT(run("render " + kCornell + " -D max_depth=-2").output,
              HasSubstr("cornell-box.xml:13: parameter 'max_depth' of integrator 'path': must be -1"));
  EXPECT_THAT(run("render " + kCornell + " --debug-pixel 9999,1").output, HasSubstr("--debug-pixel expects X,Y"));
  EXPECT_NE(run("render /nonexistent.xml").status, 0);
}

// A failed render must not touch an existing output.
TEST(RenderCommand, FailedRunKeepsThePreviousImage) {
  const auto exr = temp_dir() / "keep.exr";
  std::ofstream(exr) << "previous";
  const auto bad = temp_dir() / "bad.xml";
  std::ofstream(bad) << "<scene version='3.0.0'><shape type='cube'><ref id='x'/></shape></scene>";
  EXPECT_NE(run("render " + bad.string() + " -o " + exr.string()).status, 0);
  std::ifstream in(exr);
  std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(content, "previous");
}

}  // namespace
}  // namespace caustica
