#include "core/image/render_merge.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using testing::HasSubstr;

const std::vector<std::string> kChannels = {"R",          "G",          "B",          "albedo.R",
                                            "variance.R", "variance.G", "variance.B", "samples.Y"};

RenderFile part(const std::string& path, std::vector<float> pixel, const std::string& seed, const std::string& spp,
                const std::string& seconds) {
  return {path,
          {1, 1, kChannels, std::move(pixel)},
          {{"caustica:scene", "box.xml"},
           {"caustica:integrator", "path"},
           {"caustica:seed", seed},
           {"caustica:spp", spp},
           {"caustica:seconds", seconds},
           {"caustica:rays", "100"},
           {"caustica:interrupted", "false"}}};
}

// 2 and 6 samples: weights 2/8 and 6/8 on the means, 4/64 and 36/64 on the variances.
const RenderFile kA = part("a.exr", {1, 2, 3, 0.2f, 0.4f, 0.4f, 0.4f, 2}, "1", "2", "1.5");
const RenderFile kB = part("b.exr", {3, 2, 1, 0.6f, 0.2f, 0.2f, 0.2f, 6}, "2", "6", "2.25");

float value(const RenderFile& f, const std::string& channel) { return f.image.pixels[f.image.channel_index(channel)]; }

std::string merge_error(const std::vector<RenderFile>& parts) {
  try {
    merge_renders(parts);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(RenderMerge, MeansWeightedBySampleCount) {
  const RenderFile m = merge_renders({kA, kB});
  EXPECT_FLOAT_EQ(value(m, "R"), (2 * 1 + 6 * 3) / 8.0f);
  EXPECT_FLOAT_EQ(value(m, "G"), 2);
  EXPECT_FLOAT_EQ(value(m, "B"), (2 * 3 + 6 * 1) / 8.0f);
  EXPECT_FLOAT_EQ(value(m, "albedo.R"), (2 * 0.2f + 6 * 0.6f) / 8);
  EXPECT_FLOAT_EQ(value(m, "samples.Y"), 8);
}

TEST(RenderMerge, VariancesOfIndependentMeansCombine) {
  const RenderFile m = merge_renders({kA, kB});
  EXPECT_FLOAT_EQ(value(m, "variance.R"), (4 * 0.4f + 36 * 0.2f) / 64);
}

TEST(RenderMerge, MetadataAddsUp) {
  const RenderFile m = merge_renders({kA, kB});
  EXPECT_EQ(m.metadata.at("caustica:spp"), "8");
  EXPECT_EQ(m.metadata.at("caustica:seconds"), "3.750000");
  EXPECT_EQ(m.metadata.at("caustica:rays"), "200");
  EXPECT_EQ(m.metadata.at("caustica:seeds"), "1,2");
  EXPECT_EQ(m.metadata.count("caustica:seed"), 0u);
  EXPECT_EQ(m.metadata.at("caustica:scene"), "box.xml");
  EXPECT_EQ(m.metadata.count("caustica:samples"), 0u);  // not in the parts, so not summed
}

TEST(RenderMerge, AMergedRenderMergesAgain) {
  RenderFile ab = merge_renders({kA, kB});
  ab.path = "ab.exr";
  const RenderFile c = part("c.exr", {5, 5, 5, 0, 0, 0, 0, 8}, "3", "8", "1");
  const RenderFile m = merge_renders({ab, c});
  EXPECT_EQ(m.metadata.at("caustica:seeds"), "1,2,3");
  EXPECT_FLOAT_EQ(value(m, "R"), (8 * 2.5f + 8 * 5) / 16);
  EXPECT_EQ(m.metadata.at("caustica:spp"), "16");
  EXPECT_THAT(merge_error({ab, kA}), HasSubstr("'a.exr' and 'ab.exr' were both rendered with seed 1"));
}

TEST(RenderMerge, WithoutASamplesLayerTheSppCounts) {
  RenderFile a = kA, b = kB;
  for (RenderFile* f : {&a, &b}) {
    f->image.channels = {"R", "G", "B"};
    f->image.pixels.resize(3);
  }
  EXPECT_FLOAT_EQ(value(merge_renders({a, b}), "R"), 2.5f);
}

// Two ranges of one seed are not the same samples; they merge exactly only
// from their raw sums, which a merge by count does not read: the message
// says so, and names the ranges. Overlapping ranges do share samples.
TEST(RenderMerge, RangesOfOneSeedWithoutRawSumsAreToldWhatTheyNeed) {
  RenderFile early = kA, late = kA;
  early.metadata["caustica:first_sample"] = "0";
  late.path = "late.exr";
  late.metadata["caustica:first_sample"] = "2";
  EXPECT_THAT(merge_error({early, late}),
              HasSubstr("'late.exr' and 'a.exr' were both rendered with seed 1: samples 2..3 and 0..1: disjoint "
                        "ranges of one seed merge only from their raw sums (render each with --raw-sums)"));
  EXPECT_THAT(merge_error({late, early}), HasSubstr("with seed 1: samples 0..1 and 2..3: disjoint ranges"));
  late.metadata["caustica:first_sample"] = "1";
  EXPECT_THAT(merge_error({early, late}), HasSubstr("with seed 1: they hold the same samples"));
}

TEST(RenderMerge, RefusesRendersThatDoNotBelongTogether) {
  EXPECT_THAT(merge_error({kA, kA}), HasSubstr("rendered with seed 1: they hold the same samples"));
  RenderFile other_scene = kB;
  other_scene.metadata["caustica:scene"] = "glass.xml";
  EXPECT_THAT(merge_error({kA, other_scene}), HasSubstr("'b.exr' has another caustica:scene than 'a.exr'"));
  RenderFile other_integrator = kB;
  other_integrator.metadata["caustica:integrator"] = "direct";
  EXPECT_THAT(merge_error({kA, other_integrator}), HasSubstr("has another caustica:integrator"));
  RenderFile bigger = kB;
  bigger.image.width = 2;
  bigger.image.pixels.resize(16);
  EXPECT_THAT(merge_error({kA, bigger}), HasSubstr("'b.exr' differs in size from 'a.exr'"));
  EXPECT_EQ(merge_error({}), "nothing to merge");
}

// Metadata and sample counts are read from files anyone can write: what
// cannot be a count is refused, never converted.
TEST(RenderMerge, RefusesCountsItCannotTrust) {
  RenderFile a = kA, b = kB;
  for (RenderFile* f : {&a, &b}) {
    f->image.channels = {"R", "G", "B"};
    f->image.pixels.resize(3);
  }
  for (const char* spp : {"-2", "nan", "inf", "1e300", "two"}) {
    b.metadata["caustica:spp"] = spp;
    EXPECT_THAT(merge_error({a, b}), HasSubstr("'b.exr' has no count below 10^18 in its caustica:spp metadata (got '" +
                                               std::string(spp) + "')"));
  }
  RenderFile rays = kB;
  rays.metadata["caustica:rays"] = "-100";
  EXPECT_THAT(merge_error({kA, rays}), HasSubstr("in its caustica:rays metadata (got '-100')"));
  for (float n : {-1.0f, 2.5f, std::nanf("")}) {
    RenderFile c = kB;
    c.image.pixels.back() = n;
    EXPECT_THAT(merge_error({kA, c}), HasSubstr("in samples.Y at pixel (0, 0), not a sample count")) << n;
  }
  RenderFile inf = kB;
  inf.image.pixels[0] = std::numeric_limits<float>::infinity();
  EXPECT_THAT(merge_error({kA, inf}), HasSubstr("'b.exr' has a value that is not finite in R at pixel (0, 0)"));
}

TEST(RenderMerge, InterruptedIfAnyPartWas) {
  RenderFile b = kB;
  b.metadata["caustica:interrupted"] = "true";
  EXPECT_EQ(merge_renders({kA, b}).metadata.at("caustica:interrupted"), "true");
  EXPECT_EQ(merge_renders({kA, kB}).metadata.at("caustica:interrupted"), "false");
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
