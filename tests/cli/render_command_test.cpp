// The caustica executable end to end: what a user types and sees.

#include <OpenImageIO/imageio.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <thread>

#include "tests/support/command.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using testing::HasSubstr;

using test::run_caustica;

std::filesystem::path temp_dir() {
  const auto dir = std::filesystem::temp_directory_path() / "caustica_cli_test";
  std::filesystem::create_directories(dir);
  return dir;
}

const std::string kCornell = std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box.xml";

TEST(RenderCommand, WritesExrAndPngAndASummary) {
  const auto exr = temp_dir() / "box.exr";
  std::filesystem::remove(exr);
  const test::CommandResult r =
      run_caustica("render " + kCornell + " -o " + exr.string() + " --spp 2 -D res=24 --threads 2 --seed 3");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("24x24, 2 spp in"));
  EXPECT_THAT(r.output, HasSubstr("M rays/s"));
  EXPECT_THAT(r.output, HasSubstr("0 non-finite samples dropped"));

  auto in = OIIO::ImageInput::open(exr.string());
  ASSERT_TRUE(in);
  const OIIO::ImageSpec& spec = in->spec();
  EXPECT_EQ(spec.width, 24);
  const std::vector<std::string> layers = {"R",          "G",          "B",          "albedo.R", "albedo.G",
                                           "albedo.B",   "normal.X",   "normal.Y",   "normal.Z", "depth.T",
                                           "variance.R", "variance.G", "variance.B", "samples.Y"};
  // OpenEXR stores channels sorted by name (beauty first); compare as sets.
  std::vector<std::string> names = spec.channelnames;
  std::vector<std::string> expected = layers;
  std::sort(names.begin(), names.end());
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(names, expected);
  EXPECT_EQ(spec.channelnames[0], "R");
  // The scene's film asks for float16 by default; the first-hit layers,
  // made as the file is written, keep float, whatever their range.
  for (int c = 0; c < spec.nchannels; ++c) {
    const std::string& name = spec.channelnames[size_t(c)];
    const bool first_hit = name.rfind("albedo.", 0) == 0 || name.rfind("normal.", 0) == 0 || name == "depth.T";
    EXPECT_EQ(spec.channelformat(c), first_hit ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::HALF) << name;
  }
  EXPECT_EQ(spec.get_string_attribute("caustica:spp"), "2");
  EXPECT_EQ(spec.get_string_attribute("caustica:seed"), "3");
  EXPECT_EQ(spec.get_string_attribute("caustica:interrupted"), "false");
  EXPECT_EQ(spec.get_string_attribute("caustica:develop"), "none exposure=0.000000 display=sRGB view=Standard");
  std::vector<float> pixels(24 * 24 * 14);
  ASSERT_TRUE(in->read_image(0, 0, 0, 14, OIIO::TypeDesc::FLOAT, pixels.data()));
  double sum = 0;
  const int samples = spec.channelindex("samples.Y");
  for (size_t i = 0; i < pixels.size(); ++i) {
    EXPECT_TRUE(std::isfinite(pixels[i]));
    if (i % 14 < 3) sum += pixels[i];
    if (int(i % 14) == samples) {
      EXPECT_EQ(pixels[i], 2);  // samples per pixel
    }
  }
  EXPECT_GT(sum, 0);
  auto png = OIIO::ImageInput::open((temp_dir() / "box.png").string());
  ASSERT_TRUE(png);
  EXPECT_EQ(png->spec().format, OIIO::TypeDesc::UINT8);
}

TEST(RenderCommand, DebugPixelReplaysOneSample) {
  const test::CommandResult r = run_caustica("render " + kCornell + " -D res=24 --debug-pixel 12,12 --debug-sample 3");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("R = "));
  EXPECT_EQ(r.output, run_caustica("render " + kCornell + " -D res=24 --debug-pixel 12,12 --debug-sample 3").output);
}

TEST(RenderCommand, IntegratorOverrideAndInfo) {
  const auto exr = temp_dir() / "aov.exr";
  const test::CommandResult r =
      run_caustica("render " + kCornell + " -o " + exr.string() + " --spp 1 -D res=8 --integrator aov -q");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output, "");
  auto in = OIIO::ImageInput::open(exr.string());
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().channelnames[0], "albedo.R");
  const test::CommandResult info = run_caustica("info " + kCornell);
  EXPECT_THAT(info.output, HasSubstr("emitters: 1 (area: 1"));
}

TEST(RenderCommand, ErrorsNameTheProblem) {
  EXPECT_THAT(run_caustica("render " + kCornell + " --integrator nope").output,
              HasSubstr("caustica: error: unknown integrator 'nope'"));
  EXPECT_THAT(run_caustica("render " + kCornell + " -D spp").output, HasSubstr("-D expects name=value, got 'spp'"));
  EXPECT_THAT(run_caustica("render " + kCornell + " -D max_depth=-2").output,
              HasSubstr("cornell/room.xml:15: parameter 'max_depth' of integrator 'path': must be -1"));
  EXPECT_THAT(run_caustica("render " + kCornell + " --debug-pixel 9999,1").output,
              HasSubstr("--debug-pixel expects X,Y"));
  EXPECT_NE(run_caustica("render /nonexistent.xml").status, 0);
  EXPECT_THAT(run_caustica("render " + kCornell + " --light-selection nearest").output,
              HasSubstr("--light-selection: nearest not in {tree,power,auto}"));
}

// --light-selection reaches the render: on the hall of lamps the tree and
// the choice by power draw different lights, so their images differ, and
// each repeats itself.
TEST(RenderCommand, LightSelectionDecidesTheLightsDrawn) {
  const std::string hall = std::string(CAUSTICA_SOURCE_DIR) + "/scenes/many-lights.xml";
  const auto render = [&](const std::string& selection) {
    const auto exr = temp_dir() / ("hall-" + selection + ".exr");
    const test::CommandResult r = run_caustica("render " + hall + " -o " + exr.string() +
                                               " --spp 2 -D res=8 --threads 1 -q --light-selection " + selection);
    EXPECT_EQ(r.status, 0) << r.output;
    std::vector<float> pixels(8 * 8 * 3);
    auto in = OIIO::ImageInput::open(exr.string());
    EXPECT_TRUE(in && in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, pixels.data()));
    return pixels;
  };
  EXPECT_EQ(render("auto"), render("tree"));
  EXPECT_NE(render("tree"), render("power"));
}

TEST(RenderCommand, DevelopmentOptions) {
  const auto exr = temp_dir() / "dev.exr";
  const test::CommandResult r = run_caustica("render " + kCornell + " -o " + exr.string() +
                                             " --spp 1 -D res=16 --exr-format float --tonemap filmic" +
                                             " --exposure 1 --view ACES --look Bright --png-bits 16 -q");
  ASSERT_EQ(r.status, 0) << r.output;
  auto in = OIIO::ImageInput::open(exr.string());
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().format, OIIO::TypeDesc::FLOAT);
  EXPECT_EQ(in->spec().get_string_attribute("caustica:develop"),
            "filmic bias=2.000000 white=11.200000 exposure=1.000000 display=sRGB view=ACES look=Bright");
  auto png = OIIO::ImageInput::open((temp_dir() / "dev.png").string());
  ASSERT_TRUE(png);
  EXPECT_EQ(png->spec().format, OIIO::TypeDesc::UINT16);
  EXPECT_THAT(run_caustica("render " + kCornell + " --tonemap drago").output,
              HasSubstr("unknown tone operator 'drago' (available: aces, filmic, none, reinhard)"));
  EXPECT_THAT(run_caustica("render " + kCornell + " --view Cinema").output, HasSubstr("OpenColorIO config"));
}

// Re-developing a render gives the same PNG as developing it at render time.
TEST(TonemapCommand, RedevelopsWithoutRendering) {
  const auto exr = temp_dir() / "redevelop.exr";
  ASSERT_EQ(run_caustica("render " + kCornell + " -o " + exr.string() + " --spp 1 -D res=16 --exr-format float" +
                         " --tonemap reinhard -q")
                .status,
            0);
  const auto again = temp_dir() / "again.png";
  const test::CommandResult r =
      run_caustica("tonemap " + exr.string() + " -o " + again.string() + " --tonemap reinhard");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("reinhard key=0.180000"));
  const auto pixels = [](const std::filesystem::path& p) {
    auto in = OIIO::ImageInput::open(p.string());
    std::vector<uint8_t> data(16 * 16 * 3);
    in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, data.data());
    return data;
  };
  EXPECT_EQ(pixels(again), pixels(temp_dir() / "redevelop.png"));
  const auto brighter = temp_dir() / "brighter.png";
  ASSERT_EQ(run_caustica("tonemap " + exr.string() + " -o " + brighter.string() + " --exposure 2").status, 0);
  EXPECT_NE(pixels(brighter), pixels(again));
  EXPECT_THAT(run_caustica("tonemap /nonexistent.exr -o x.png").output, HasSubstr("nonexistent.exr"));
}

// Glare from the command line: recorded in the development settings with
// the camera's degrees per pixel, which the EXR keeps for `tonemap`; an
// image without that record, or a camera without a field of view, is
// refused with what to give instead.
TEST(TonemapCommand, Glare) {
  const auto exr = temp_dir() / "glare.exr";
  const test::CommandResult r = run_caustica("render " + kCornell + " -o " + exr.string() +
                                             " --spp 1 -D res=16 --exr-format float --glare whole -q");
  ASSERT_EQ(r.status, 0) << r.output;
  auto in = OIIO::ImageInput::open(exr.string());
  ASSERT_TRUE(in);
  const std::string recorded = in->spec().get_string_attribute("caustica:degrees_per_pixel");
  // The Cornell box's 39.3077-degree view over 16 pixels.
  const double expected = 2 * std::atan(std::tan(39.3077 / 2 * M_PI / 180) / 16) * 180 / M_PI;
  EXPECT_NEAR(std::stod(recorded), expected, 1e-4 * expected);
  EXPECT_THAT(in->spec().get_string_attribute("caustica:develop"), HasSubstr("glare=whole degrees_per_pixel=2.55"));
  in.reset();

  const auto pixels = [](const std::filesystem::path& p) {
    auto png = OIIO::ImageInput::open(p.string());
    std::vector<uint8_t> data(16 * 16 * 3);
    png->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, data.data());
    return data;
  };
  const auto plain = temp_dir() / "glare-plain.png", clipped = temp_dir() / "glare-clipped.png";
  ASSERT_EQ(run_caustica("tonemap " + exr.string() + " -o " + plain.string()).status, 0);
  const test::CommandResult c =
      run_caustica("tonemap " + exr.string() + " -o " + clipped.string() + " --glare clipped");
  ASSERT_EQ(c.status, 0) << c.output;
  EXPECT_THAT(c.output, HasSubstr("glare=clipped degrees_per_pixel=2.55"));
  EXPECT_NE(pixels(plain), pixels(clipped));
  EXPECT_NE(pixels(clipped), pixels(temp_dir() / "glare.png")) << "whole glare spreads the walls too";
  const test::CommandResult dim =
      run_caustica("tonemap " + exr.string() + " -o " + clipped.string() + " --glare clipped --exposure -20");
  EXPECT_THAT(dim.output, HasSubstr("glare skipped, no pixel exceeds the display's range"));
  const auto dim_plain = temp_dir() / "glare-dim.png";
  ASSERT_EQ(run_caustica("tonemap " + exr.string() + " -o " + dim_plain.string() + " --exposure -20").status, 0);
  EXPECT_EQ(pixels(clipped), pixels(dim_plain)) << "at -20 stops nothing is beyond the range";

  const auto bare = temp_dir() / "bare.exr";
  {
    std::vector<float> rgb(8 * 8 * 3, 2.0f);
    auto out = OIIO::ImageOutput::create(bare.string());
    ASSERT_TRUE(out->open(bare.string(), OIIO::ImageSpec(8, 8, 3, OIIO::TypeDesc::FLOAT)));
    out->write_image(OIIO::TypeDesc::FLOAT, rgb.data());
  }
  EXPECT_THAT(run_caustica("tonemap " + bare.string() + " -o " + plain.string() + " --glare whole").output,
              HasSubstr("which the image does not record: give --degrees-per-pixel"));
  EXPECT_EQ(
      run_caustica("tonemap " + bare.string() + " -o " + plain.string() + " --glare whole --degrees-per-pixel 0.1")
          .status,
      0);
  EXPECT_NE(run_caustica("tonemap " + bare.string() + " -o " + plain.string() + " --glare bloom").status, 0);
  EXPECT_NE(run_caustica("tonemap " + bare.string() + " -o " + plain.string() + " --glare whole --degrees-per-pixel 0")
                .status,
            0);
  const auto ortho = temp_dir() / "ortho.xml";
  std::ofstream(ortho) << "<scene version='3.0.0'><sensor type='orthographic'/></scene>";
  EXPECT_THAT(run_caustica("render " + ortho.string() + " --spp 1 --glare whole -q").output,
              HasSubstr("glare needs a camera with a field of view (this one's rays are parallel)"));
}

// Starts a render of `scene` at 32x32 with `args`, sends `signal` once it
// is rendering, and returns the spp its EXR records, after checking the
// file is a whole image marked interrupted whose every pixel holds that
// many samples.
int interrupted_render(int signal, const std::string& scene, const std::string& name, std::vector<std::string> args) {
  const auto exr = temp_dir() / name;
  std::filesystem::remove(exr);
  int out[2];
  if (pipe(out) != 0) return -1;
  const pid_t pid = fork();
  if (pid < 0) return -1;
  if (pid == 0) {
    dup2(out[1], STDOUT_FILENO);
    close(out[0]);
    std::vector<std::string> words = {CAUSTICA_BINARY, "render",    scene, "-o" + exr.string(), "-D",
                                      "res=32",        "--threads", "1"};
    words.insert(words.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    execv(CAUSTICA_BINARY, argv.data());
    _exit(127);
  }
  close(out[1]);
  // The plan's line comes once the scene is loaded (a stop during a mesh
  // load ends the run without an image, by design); the pause then lets
  // the render get going, and whenever the signal arrives it ends the
  // render long before it would end by itself.
  char c = 0;
  while (read(out[0], &c, 1) == 1 && c != '\n') {
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  kill(pid, signal);
  // Read on to the end: a closed pipe would end the run with SIGPIPE.
  while (read(out[0], &c, 1) == 1) {
  }
  close(out[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  auto in = OIIO::ImageInput::open(exr.string());
  if (!in) {
    ADD_FAILURE() << "no image " << exr;
    return -1;
  }
  const int spp = std::stoi(in->spec().get_string_attribute("caustica:spp"));
  EXPECT_EQ(in->spec().get_string_attribute("caustica:interrupted"), "true");
  const int channels = in->spec().nchannels;
  std::vector<float> pixels(32 * 32 * size_t(channels));
  EXPECT_TRUE(in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data()));
  const int samples = in->spec().channelindex("samples.Y");
  EXPECT_GE(samples, 0);
  for (size_t i = size_t(samples); i < pixels.size(); i += size_t(channels)) EXPECT_EQ(pixels[i], float(spp));
  for (float v : pixels) EXPECT_TRUE(std::isfinite(v));
  return spp;
}

// Ctrl-C, and SIGTERM as `timeout` and cluster schedulers send it, stop at
// the next pass and still write a valid image, with the number of samples
// it really has.
TEST(RenderCommand, InterruptWritesThePartialImage) {
  for (int signal : {SIGINT, SIGTERM}) {
    const int spp = interrupted_render(signal, kCornell, "interrupted.exr", {"--spp", "100000"});
    EXPECT_GT(spp, 0) << signal;
    EXPECT_LT(spp, 100000) << signal;
  }
}

// A production-size photon round is abandoned, not finished, when the stop
// arrives during it: one round of 10^9 photons would take many minutes, so
// an image with zero samples comes back within the test's patience.
TEST(RenderCommand, InterruptDuringAPhotonRoundWritesAnEmptyImage) {
  const std::string glass = std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box-glass.xml";
  for (const char* integrator : {"photon:photons=1000000000", "sppm:photons=1000000000"})
    EXPECT_EQ(interrupted_render(SIGTERM, glass, "photon-round.exr", {"--integrator", integrator}), 0) << integrator;
}

// A failed render must not touch an existing output.
TEST(RenderCommand, FailedRunKeepsThePreviousImage) {
  const auto exr = temp_dir() / "keep.exr";
  std::ofstream(exr) << "previous";
  const auto bad = temp_dir() / "bad.xml";
  std::ofstream(bad) << "<scene version='3.0.0'><shape type='cube'><ref id='x'/></shape></scene>";
  EXPECT_NE(run_caustica("render " + bad.string() + " -o " + exr.string()).status, 0);
  std::ifstream in(exr);
  std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(content, "previous");
}

// TBB cannot make a hundred thousand threads; the option is bounded.
TEST(RenderCommand, ThreadCountIsBounded) {
  const test::CommandResult r = run_caustica("render " + kCornell + " -D res=8 --spp 1 -q --threads 100000");
  EXPECT_NE(r.status, 0);
  EXPECT_THAT(r.output, HasSubstr("--threads: Value 100000 not in range"));
}

// Numbers a render cannot use are refused, not replaced by a default.
TEST(RenderCommand, NumericOptionsAreChecked) {
  const std::string render = "render " + kCornell + " -D res=8 -q -o " + (temp_dir() / "numbers.exr").string();
  for (const auto& [option, message] :
       {std::pair<std::string, std::string>{"--spp 0", "--spp: Value 0 not in range"},
        {"--time 0", "--time: '0' is not a finite number above zero"},
        {"--time -1", "--time: '-1' is not a finite number above zero"},
        {"--time nan", "--time: 'nan' is not a finite number above zero"},
        {"--time inf", "--time: 'inf' is not a finite number above zero"},
        {"--spp 1 --exposure nan", "--exposure: 'nan' is not a finite number"},
        {"--spp 1 --exposure 1e30", "--exposure: Value 1e30 not in range"},
        // Unsigned parses would wrap these to 2^64 - 1 and a black image.
        {"--spp 1 --first-sample -1", "--first-sample: '-1' is not a whole number from 0 to 2^62"},
        {"--spp 4 --first-sample 18446744073709551614",
         "--first-sample: '18446744073709551614' is not a whole number from 0 to 2^62"},
        {"--spp 1 --first-sample 4611686018427387905", "is not a whole number from 0 to 2^62"},
        {"--spp 1 --first-sample +3", "'+3' is not a whole number"},
        {"--spp 1 --seed -1", "--seed: '-1' is not a whole number from 0 to 2^64 - 1"},
        {"--spp 1 --seed 18446744073709551616",
         "--seed: '18446744073709551616' is not a whole number from 0 to 2^64 - 1"},
        {"--spp 1 --debug-pixel 1,1 --debug-sample -2", "--debug-sample: '-2' is not a whole number"}}) {
    const test::CommandResult r = run_caustica(render + " " + option);
    EXPECT_NE(r.status, 0) << option;
    EXPECT_THAT(r.output, HasSubstr(message)) << option;
  }
  const test::CommandResult compare = run_caustica("compare " + kCornell + " " + kCornell + " --epsilon nan");
  EXPECT_NE(compare.status, 0);
  EXPECT_THAT(compare.output, HasSubstr("--epsilon: 'nan' is not a finite number above zero"));
}

TEST(RenderCommand, UnusedDefinesAreReported) {
  const test::CommandResult r =
      run_caustica("render " + kCornell + " -D res=8 -D rse=4 --spp 1 -q -o " + (temp_dir() / "defines.exr").string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output,
              HasSubstr("caustica: warning: " + kCornell + ": -D rse is not used by the scene (no $rse in it)"));
  EXPECT_THAT(r.output, testing::Not(HasSubstr("-D res ")));
}

// A small emitter of radiance 1e5 puts values beyond half float's 65504 in
// the image, and one of 1e30 variances beyond float's range: neither file
// may hold an infinity.
TEST(RenderCommand, OutputsHoldNoInfinity) {
  const auto scene = temp_dir() / "bright.xml";
  std::ofstream(scene) << R"(<scene version="3.0.0">
  <sensor type="perspective"><transform name="to_world"><lookat origin="0,0,5" target="0,0,0"/></transform>
    <film type="hdrfilm"><integer name="width" value="16"/><integer name="height" value="16"/></film>
  </sensor>
  <shape type="sphere"><float name="radius" value="0.5"/>
    <emitter type="area"><rgb name="radiance" value="$L"/></emitter></shape>
  <shape type="rectangle"><transform name="to_world"><translate z="-1"/></transform></shape>
</scene>)";
  for (const std::string format : {"half", "float"})
    for (const std::string radiance : {"1e5", "1e30"}) {
      const auto exr = temp_dir() / "bright.exr";
      const test::CommandResult r = run_caustica("render " + scene.string() + " -D L=" + radiance +
                                                 " --spp 4 -q --exr-format " + format + " -o " + exr.string());
      ASSERT_EQ(r.status, 0) << r.output;
      if (format == "half") {
        EXPECT_THAT(r.output, HasSubstr("values exceed 65504, the largest half float"));
      }
      if (radiance == "1e30") {
        EXPECT_THAT(r.output, HasSubstr("variance values exceed the float range"));
      }
      auto in = OIIO::ImageInput::open(exr.string());
      ASSERT_TRUE(in);
      EXPECT_EQ(in->spec().format, OIIO::TypeDesc::FLOAT) << format << " " << radiance;
      std::vector<float> pixels(size_t(16) * 16 * in->spec().nchannels);
      ASSERT_TRUE(in->read_image(0, 0, 0, in->spec().nchannels, OIIO::TypeDesc::FLOAT, pixels.data()));
      EXPECT_EQ(std::count_if(pixels.begin(), pixels.end(), [](float v) { return !std::isfinite(v); }), 0)
          << format << " " << radiance;
    }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
