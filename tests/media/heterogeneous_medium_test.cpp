// The heterogeneous medium and its grids: ratio tracking's mean against
// the transmittance through a known grid (z-tests), delta tracking's
// collision distances against the analytic density (chi-square), spectral
// tracking's unbiasedness per channel, the grid's interpolation and bounds,
// bad .vol files, and the extremes of extinction. The oracle integrates the
// grid's interpolation numerically with its own code. Fixed seeds; the
// file's statistical tests share 0.1%, Sidak-corrected.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "tests/support/chi2.h"
#include "tests/support/media.h"
#include "tests/support/samplers.h"
#include "tests/support/test_scenes.h"
#include "tests/support/vol_writer.h"
#include "tests/support/z_test.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

namespace fs = std::filesystem;
using testing::HasSubstr;

// 10 ratio- and delta-tracking z-tests, 1 chi-square, 12 spectral z-tests.
const double kAlpha = 1 - std::pow(1 - 0.001, 1.0 / 23);

const float kScale = 2;
// Voxel values along x of a 4 x 1 x 1 grid, per channel.
const float kRamp[3][4] = {{1, 3, 0, 5}, {2, 2, 1, 0.5f}, {0.2f, 4, 4, 0}};

fs::path grid_file(const std::string& name, int channels) {
  const fs::path dir = fs::temp_directory_path() / "caustica_heterogeneous_test";
  fs::create_directories(dir);
  std::vector<float> values;
  for (int x = 0; x < 4; ++x)
    for (int c = 0; c < channels; ++c) values.push_back(kRamp[c][x]);
  const fs::path file = dir / name;
  test::write_vol_file(file, 4, 1, 1, channels, values);
  return file;
}

std::shared_ptr<const Medium> ramp_medium(int channels, const std::string& albedo, int majorant_factor = 8,
                                          float scale = kScale) {
  return test::make_medium(
      "<medium type='heterogeneous'><volume type='gridvolume' name='sigma_t'>"
      "<string name='filename' value='" +
      grid_file("ramp" + std::to_string(channels) + ".vol", channels).string() +
      "'/></volume><rgb name='albedo' value='" + albedo + "'/><float name='scale' value='" + std::to_string(scale) +
      "'/><integer name='majorant_resolution_factor' value='" + std::to_string(majorant_factor) + "'/></medium>");
}

// The oracle: the grid's extinction at x in [0, 1], interpolated linearly
// between voxel centres (i + 0.5) / 4 and constant beyond the outer ones.
double sigma_at(double x, int channel) {
  const double g = std::clamp(x * 4 - 0.5, 0.0, 3.0);
  const int i = std::min(2, int(g));
  return kScale * (kRamp[channel][i] + (g - i) * (kRamp[channel][i + 1] - kRamp[channel][i]));
}

// The optical depth from x = 0 to x, by the midpoint rule.
double depth_to(double x, int channel) {
  const int n = 20000;
  double sum = 0;
  for (int i = 0; i < n; ++i) sum += sigma_at((i + 0.5) * x / n, channel);
  return sum * x / n;
}

struct Samples {
  std::unique_ptr<Sampler> sampler = test::make_sampler("independent");
  Sampler& at(uint64_t i) {
    sampler->start_sample(SampleKey::camera({0, 0}), i, 11);
    return *sampler;
  }
};

void expect_mean(const std::vector<double>& xs, double expected, const std::string& what) {
  double sum = 0, sum2 = 0;
  for (double x : xs) {
    sum += x;
    sum2 += x * x;
  }
  const double n = double(xs.size()), mean = sum / n, var = sum2 / n - mean * mean;
  EXPECT_LT(std::abs(mean - expected), test::two_sided_z_critical(kAlpha) * std::sqrt(var / n) + 1e-7)
      << what << ": mean " << mean << ", expected " << expected;
}

TEST(HeterogeneousMedium, RatioTrackingMeetsTheTransmittance) {
  // From x = -0.5 across the grid (the ray's direction has length 2).
  const Ray ray{{-0.5f, 0.5f, 0.5f}, {2, 0, 0}};
  // One majorant for the grid, and one per voxel (the traversal crosses cells).
  for (int factor : {0, 1}) {
    const auto m = ramp_medium(1, "0.5", factor);
    Samples s;
    for (float t_max : {0.6f, 2.0f}) {
      std::vector<double> estimates;
      for (int i = 0; i < 40000; ++i) estimates.push_back(m->transmittance(ray, t_max, s.at(i)).r);
      const double x_end = std::min(1.0, -0.5 + 2.0 * t_max);
      expect_mean(estimates, std::exp(-depth_to(x_end, 0)),
                  "majorant factor " + std::to_string(factor) + ", t_max " + std::to_string(t_max));
    }
    // Diagonally, leaving through the face x = 1 at t = 1: the grid varies
    // along x alone, so the depth is |d| times that along x.
    const Ray diagonal{{0, 0.2f, 0.1f}, {1, 0.5f, 0.3f}};
    std::vector<double> estimates;
    for (int i = 0; i < 40000; ++i) estimates.push_back(m->transmittance(diagonal, 5, s.at(i)).r);
    expect_mean(estimates, std::exp(-length(diagonal.d) * depth_to(1, 0)),
                "diagonal, majorant factor " + std::to_string(factor));
  }
}

TEST(HeterogeneousMedium, TrackingSkipsEmptyCellsAndNoOther) {
  // Empty but for its last voxels: six of eight majorant cells are zero,
  // and the traversal must hand the two others their own bounds.
  const std::vector<float> values = {0, 0, 0, 0, 0, 0, 0, 4};
  const fs::path dir = fs::temp_directory_path() / "caustica_heterogeneous_test";
  fs::create_directories(dir);
  test::write_vol_file(dir / "corner.vol", 8, 1, 1, 1, values);
  const auto m = test::make_medium(
      "<medium type='heterogeneous'><volume type='gridvolume' name='sigma_t'><string name='filename' value='" +
      (dir / "corner.vol").string() + "'/></volume><integer name='majorant_resolution_factor' value='1'/></medium>");
  // The extinction rises linearly from 0 at voxel 6's centre (x = 13/16) to
  // 4 at voxel 7's (x = 15/16), then stays 4: a depth of 4/16 + 4/16.
  const double depth = 0.5;
  Samples s;
  std::vector<double> estimates;
  for (int i = 0; i < 40000; ++i) estimates.push_back(m->transmittance({{-0.5f, 0.5f, 0.5f}, {1, 0, 0}}, 2, s.at(i)).r);
  expect_mean(estimates, std::exp(-depth), "ratio tracking");
  int passed = 0;
  const int n = 40000;
  for (int i = 0; i < n; ++i)
    passed += !m->sample_free_flight({{-0.5f, 0.5f, 0.5f}, {1, 0, 0}}, 2, Color(1), s.at(i)).scattered;
  // Passing is a Bernoulli trial of probability exp(-depth).
  const double p = std::exp(-depth);
  EXPECT_LT(std::abs(passed / double(n) - p), test::two_sided_z_critical(kAlpha) * std::sqrt(p * (1 - p) / n));
  // From inside the grid, in the rising voxel: the depth from x = 0.85 by the midpoint rule.
  double inside_depth = 0;
  for (int i = 0; i < 10000; ++i) {
    const double x = 0.85 + (i + 0.5) * 0.15 / 10000;
    inside_depth += std::clamp((x - 13.0 / 16) * 32, 0.0, 4.0) * 0.15 / 10000;
  }
  estimates.clear();
  for (int i = 0; i < 40000; ++i) estimates.push_back(m->transmittance({{0.85f, 0.5f, 0.5f}, {1, 0, 0}}, 2, s.at(i)).r);
  expect_mean(estimates, std::exp(-inside_depth), "ratio tracking from inside");
}

TEST(HeterogeneousMedium, RatioTrackingRouletteKeepsTheMeanWhereNearlyOpaque) {
  // One voxel of extinction 10 under a majorant of 20: each tentative
  // collision halves the estimate, so below 1e-3 Russian roulette decides,
  // and the mean must stay exp(-10) across the unit cube.
  const fs::path dir = fs::temp_directory_path() / "caustica_heterogeneous_test";
  fs::create_directories(dir);
  const fs::path file = dir / "one.vol";
  test::write_vol_file(file, 1, 1, 1, 1, {10});
  const auto opaque = test::make_medium(
      "<medium type='heterogeneous'><volume type='gridvolume' name='sigma_t'><string name='filename' value='" +
      file.string() +
      "'/></volume><integer name='majorant_resolution_factor' value='0'/><float name='majorant_factor' "
      "value='2'/></medium>");
  Samples s;
  std::vector<double> estimates;
  for (int i = 0; i < 200000; ++i)
    estimates.push_back(opaque->transmittance({{-1, 0.5f, 0.5f}, {1, 0, 0}}, 3, s.at(i)).r);
  expect_mean(estimates, std::exp(-10.0), "nearly opaque");
}

TEST(HeterogeneousMedium, DeltaTrackingCollidesWithTheAnalyticDensity) {
  const auto m = ramp_medium(1, "0.6", 1);
  const int bins = 20, n = 200000;
  std::vector<double> observed(bins + 1, 0), expected(bins + 1, 0);
  Samples s;
  for (int i = 0; i < n; ++i) {
    const FreeFlight f = m->sample_free_flight({{0, 0.5f, 0.5f}, {1, 0, 0}}, 1, Color(1), s.at(i));
    if (f.scattered) {
      ASSERT_NEAR(f.weight.r, 0.6f, 1e-5f);
      ++observed[std::min(bins - 1, int(f.t * bins))];
    } else {
      ASSERT_NEAR(f.weight.r, 1, 1e-6f);
      ++observed[bins];
    }
  }
  for (int b = 0; b < bins; ++b)
    expected[b] = n * (std::exp(-depth_to(double(b) / bins, 0)) - std::exp(-depth_to(double(b + 1) / bins, 0)));
  expected[bins] = n * std::exp(-depth_to(1, 0));
  const auto chi2 = test::chi2_test_counts(observed, expected);
  EXPECT_GT(chi2.p_value, kAlpha) << chi2.report;
}

TEST(HeterogeneousMedium, SpectralTrackingIsUnbiasedPerChannel) {
  // For a grey path and for one whose weight lies mostly in the last channel.
  const Color albedo(0.9f, 0.5f, 0.3f);
  const auto m = ramp_medium(3, "0.9, 0.5, 0.3");
  ASSERT_TRUE(m->is_chromatic());
  for (const Color beta : {Color(1), Color(0.05f, 0.3f, 1)}) {
    std::vector<double> pass[3], first_half[3];
    Samples s;
    for (int i = 0; i < 100000; ++i) {
      const FreeFlight f = m->sample_free_flight({{0, 0.5f, 0.5f}, {1, 0, 0}}, 1, beta, s.at(i));
      for (int c = 0; c < 3; ++c) {
        pass[c].push_back(f.scattered ? 0 : f.weight[c]);
        first_half[c].push_back(f.scattered && f.t < 0.5f ? f.weight[c] : 0);
      }
    }
    const std::string path = " (path weight " + std::to_string(beta.r) + ")";
    for (int c = 0; c < 3; ++c) {
      expect_mean(pass[c], std::exp(-depth_to(1, c)), "passing, channel " + std::to_string(c) + path);
      expect_mean(first_half[c], albedo[c] * (1 - std::exp(-depth_to(0.5, c))),
                  "scattering in the first half, channel " + std::to_string(c) + path);
    }
  }
}

TEST(HeterogeneousMedium, EmptyAndDenseGridsStayFinite) {
  Samples s;
  const auto empty = test::make_medium(
      "<medium type='heterogeneous'><volume type='gridvolume' name='sigma_t'><string name='filename' value='" +
      grid_file("ramp1.vol", 1).string() + "'/></volume><float name='scale' value='0'/></medium>");
  const FreeFlight f = empty->sample_free_flight({{0, 0.5f, 0.5f}, {1, 0, 0}}, kInfinity, Color(1), s.at(0));
  EXPECT_FALSE(f.scattered);
  EXPECT_EQ(f.weight, Color(1));
  EXPECT_EQ(empty->transmittance({{0, 0.5f, 0.5f}, {1, 0, 0}}, kInfinity, s.at(0)), Color(1));
  const auto dense = test::make_medium(
      "<medium type='heterogeneous'><volume type='gridvolume' name='sigma_t'><string name='filename' value='" +
      grid_file("ramp1.vol", 1).string() +
      "'/></volume><float name='scale' value='1e6'/><integer name='majorant_resolution_factor' value='1'/></medium>");
  for (int i = 0; i < 100; ++i) {
    // Through the third voxel, where the grid is 0, and on into the dense fourth.
    const FreeFlight d = dense->sample_free_flight({{0.6f, 0.5f, 0.5f}, {1, 0, 0}}, 1, Color(1), s.at(i));
    EXPECT_TRUE(d.scattered);
    EXPECT_TRUE(d.weight.is_finite());
    EXPECT_EQ(dense->transmittance({{0.6f, 0.5f, 0.5f}, {1, 0, 0}}, 1, s.at(i)), Color(0));
  }
}

TEST(GridVolume, InterpolatesBetweenVoxelCentresAndBoundsEveryCell) {
  const auto grid = test::make_grid_volume(grid_file("ramp1.vol", 1));
  for (int i = 0; i < 4; ++i) EXPECT_FLOAT_EQ(grid->eval({(i + 0.5f) / 4, 0.5f, 0.5f}).r, kRamp[0][i]) << i;
  EXPECT_FLOAT_EQ(grid->eval({0.5f, 0.2f, 0.9f}).r, 1.5f);  // halfway between 3 and 0
  EXPECT_FLOAT_EQ(grid->eval({0.05f, 0.5f, 0.5f}).r, 1);    // clamped before the first centre
  EXPECT_EQ(grid->eval({1.1f, 0.5f, 0.5f}), Color());       // outside the grid
  EXPECT_FLOAT_EQ(test::make_grid_volume(grid_file("ramp1.vol", 1), "nearest")->eval({0.3f, 0.5f, 0.5f}).r, 3);
  // Every point of a cell stays below the cell's bound.
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0, 1);
  for (int i = 0; i < 2000; ++i) {
    Bounds3 cell;
    cell.expand({u(rng), u(rng), u(rng)});
    cell.expand({u(rng), u(rng), u(rng)});
    const Vec3 p = cell.lo + (cell.hi - cell.lo) * Vec3(u(rng), u(rng), u(rng));
    ASSERT_LE(grid->eval(p).r, grid->max_in(cell)) << p.x;
  }
}

TEST(GridVolume, BadFilesAndParametersAreErrors) {
  const fs::path dir = fs::temp_directory_path() / "caustica_heterogeneous_test";
  fs::create_directories(dir);
  const auto error_for = [&](const std::string& bytes) {
    const fs::path file = dir / "bad.vol";
    std::ofstream(file, std::ios::binary) << bytes;
    return test::load_error(
        "<scene version='3.0.0'>\n<medium type='heterogeneous' id='m'>\n<volume "
        "type='gridvolume' name='sigma_t'>\n<string name='filename' value='" +
            file.string() + "'/></volume></medium></scene>",
        "bad.xml");
  };
  const std::string where = "bad.xml:4: parameter 'filename' of volume 'gridvolume': " + (dir / "bad.vol").string();
  EXPECT_THAT(error_for("VOX"), HasSubstr(where + ": is too short for a volume header (3 bytes"));
  std::string header(48, '\0');
  EXPECT_THAT(error_for(header), HasSubstr(where + ": is not a Mitsuba volume"));
  const fs::path good = grid_file("ramp1.vol", 1);
  std::ifstream in(good, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::string v = bytes;
  v[3] = 2;
  EXPECT_THAT(error_for(v), HasSubstr(where + ": has volume format version 2; only 3 is read"));
  v = bytes;
  v[4] = 2;
  EXPECT_THAT(error_for(v), HasSubstr(where + ": stores its values with encoding 2; only 1 (32-bit float) is read"));
  v = bytes;
  v[20] = 2;
  EXPECT_THAT(error_for(v), HasSubstr(where + ": declares 2 channels; 1 or 3 are read"));
  EXPECT_THAT(error_for(bytes.substr(0, bytes.size() - 4)),
              HasSubstr(where + ": declares 4 x 1 x 1 x 1 values (16 bytes) but holds 12"));
  v = bytes;
  v[8] = char(0xff), v[9] = char(0xff), v[10] = char(0xff), v[11] = char(0x7f);
  v[12] = char(0xff), v[13] = char(0xff), v[14] = char(0xff), v[15] = char(0x7f);
  EXPECT_THAT(error_for(v), HasSubstr("voxels, more than 2^28"));
  v = bytes;
  v[48 + 7] = char(0xc0);  // the second value, 3, made -3
  EXPECT_THAT(error_for(v), HasSubstr(where + ": holds the value -3.000000 at byte 52; values must be finite and at "
                                              "least 0"));
  EXPECT_THAT(error_for("VOL"), HasSubstr("is too short"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'>\n<medium type='heterogeneous' id='m'>\n<volume "
                               "type='gridvolume' name='albedo'>\n<string name='filename' value='" +
                                   grid_file("ramp3.vol", 3).string() + "'/></volume></medium></scene>",
                               "bad.xml"),
              HasSubstr("bad.xml:3: parameter 'albedo' of medium 'heterogeneous': must lie in [0, 1] everywhere"));
  EXPECT_THAT(test::load_error("<scene version='3.0.0'>\n<medium type='heterogeneous' id='m'>\n<volume "
                               "type='gridvolume' name='sigma_t'>\n<string name='filename' value='" +
                                   good.string() +
                                   "'/>\n<string name='filter_type' value='cubic'/></volume>"
                                   "</medium></scene>",
                               "bad.xml"),
              HasSubstr("bad.xml:5: parameter 'filter_type' of volume 'gridvolume': must be trilinear or nearest"));
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
