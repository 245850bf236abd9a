// The guiding tree over space: regions found by position, halved where
// their records exceed the threshold, both halves taking the records'
// distribution and radiance, and the memory cap holding refinement back.

#include "integrators/path/guiding/spatial_tree.h"

#include <gtest/gtest.h>

#include <cmath>

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

Bounds3 unit_box() {
  Bounds3 b;
  b.expand(Vec3{0, 0, 0});
  b.expand(Vec3{1, 1, 1});
  return b;
}

// `n` records in the region at p, all toward the square's point (0.1, 0.1).
void record(GuidingTree& tree, Vec3 p, int n) {
  for (int i = 0; i < n; ++i) tree.region_at(p).record(0, {0.1f, 0.1f}, 1);
}

TEST(GuidingTree, HalvesRegionsHoldingManyRecordsAlongXFirst) {
  GuidingTree tree(unit_box());
  GuidingRefinement settings;
  settings.spatial_threshold = 100;
  record(tree, {0.2f, 0.5f, 0.5f}, 150);  // above 100 * sqrt(1): halved once
  tree.refine(settings, 1);
  ASSERT_EQ(tree.regions(), 2u);
  GuidingRegion& left = tree.region_at({0.2f, 0.5f, 0.5f});
  GuidingRegion& right = tree.region_at({0.8f, 0.5f, 0.5f});
  EXPECT_NE(&left, &right);
  // Both halves sample by the records: all toward (0.1, 0.1).
  EXPECT_GT(left.guides[0].sampling.pdf({0.1f, 0.1f}), 1);
  EXPECT_GT(right.guides[0].sampling.pdf({0.1f, 0.1f}), 1);
  EXPECT_EQ(left.guides[0].sampling.pdf({0.9f, 0.9f}), 0);
  // The halves meet at x = 0.5 of the cube around the box; y does not divide them.
  EXPECT_EQ(&tree.region_at({0.2f, 0.1f, 0.9f}), &left);

  // At 4 samples per pixel the threshold is 100 * sqrt(4) = 200: 600
  // records halve to 300 and again to 150, four regions where there was
  // one; the right half, holding none, stays whole.
  record(tree, {0.2f, 0.5f, 0.5f}, 600);
  tree.refine(settings, 4);
  EXPECT_EQ(tree.regions(), 5u);
  EXPECT_FALSE(tree.capped());
}

TEST(GuidingTree, RegionsWithFewRecordsStayWhole) {
  GuidingTree tree(unit_box());
  GuidingRefinement settings;
  settings.spatial_threshold = 100;
  record(tree, {0.5f, 0.5f, 0.5f}, 100);  // not above 100
  tree.refine(settings, 1);
  EXPECT_EQ(tree.regions(), 1u);
  // Records are counted afresh each pass.
  record(tree, {0.5f, 0.5f, 0.5f}, 100);
  tree.refine(settings, 1);
  EXPECT_EQ(tree.regions(), 1u);
}

// A guide learnt from fewer than min_records records stays empty (its
// paths sample the BSDF alone); from min_records on it samples by them.
// Halving a region does not thin its halves' guides: both learnt from all
// of its records.
TEST(GuidingTree, GuidesLearntFromFewRecordsStayEmpty) {
  GuidingTree tree(unit_box());
  GuidingRefinement settings;
  settings.spatial_threshold = 100;
  settings.min_records = 120;
  record(tree, {0.2f, 0.5f, 0.5f}, 119);
  tree.refine(settings, 1);
  ASSERT_EQ(tree.regions(), 2u);
  EXPECT_TRUE(tree.region_at({0.2f, 0.5f, 0.5f}).guides[0].sampling.empty());
  EXPECT_TRUE(tree.region_at({0.8f, 0.5f, 0.5f}).guides[0].sampling.empty());

  GuidingTree enough(unit_box());
  record(enough, {0.2f, 0.5f, 0.5f}, 120);
  enough.refine(settings, 1);
  ASSERT_EQ(enough.regions(), 2u);
  EXPECT_GT(enough.region_at({0.2f, 0.5f, 0.5f}).guides[0].sampling.pdf({0.1f, 0.1f}), 1);
  EXPECT_GT(enough.region_at({0.8f, 0.5f, 0.5f}).guides[0].sampling.pdf({0.1f, 0.1f}), 1);
  // Another bucket of the same region took no records: still unguided.
  EXPECT_TRUE(enough.region_at({0.2f, 0.5f, 0.5f}).guides[1].sampling.empty());

  // Records are counted afresh each pass: 119 in the next leave it empty again.
  record(enough, {0.2f, 0.5f, 0.5f}, 119);
  enough.refine(settings, 1);
  EXPECT_TRUE(enough.region_at({0.2f, 0.5f, 0.5f}).guides[0].sampling.empty());
}

// The radiance a guide learns is the mean of its pass's records, from
// kMinRadianceRecords of them on; with fewer it keeps what it knew, and a
// halved region's halves both keep the whole's.
TEST(GuidingTree, LearnsEachGuidesMeanRadiance) {
  GuidingTree tree(unit_box());
  GuidingRefinement settings;
  settings.spatial_threshold = 100;
  EXPECT_EQ(tree.region_at({0.2f, 0.5f, 0.5f}).guides[2].radiance, 0);  // unknown
  DirectionalGuide& guide = tree.region_at({0.2f, 0.5f, 0.5f}).guides[2];
  for (int i = 0; i < 16; ++i) guide.record_radiance(i % 2 ? 3.0 : 0.0);  // mean 1.5
  record(tree, {0.2f, 0.5f, 0.5f}, 150);
  tree.refine(settings, 1);
  ASSERT_EQ(tree.regions(), 2u);
  EXPECT_FLOAT_EQ(tree.region_at({0.2f, 0.5f, 0.5f}).guides[2].radiance, 1.5f);
  EXPECT_FLOAT_EQ(tree.region_at({0.8f, 0.5f, 0.5f}).guides[2].radiance, 1.5f);
  EXPECT_EQ(tree.region_at({0.2f, 0.5f, 0.5f}).guides[0].radiance, 0);  // its own records were directions only

  // 15 records are too few to replace it; 16 of 4 are not.
  DirectionalGuide& left = tree.region_at({0.2f, 0.5f, 0.5f}).guides[2];
  for (int i = 0; i < 15; ++i) left.record_radiance(10);
  tree.refine(settings, 1);
  EXPECT_FLOAT_EQ(tree.region_at({0.2f, 0.5f, 0.5f}).guides[2].radiance, 1.5f);
  DirectionalGuide& again = tree.region_at({0.2f, 0.5f, 0.5f}).guides[2];
  for (int i = 0; i < 16; ++i) again.record_radiance(4);
  tree.refine(settings, 1);
  EXPECT_FLOAT_EQ(tree.region_at({0.2f, 0.5f, 0.5f}).guides[2].radiance, 4.0f);
}

// A guide learns that its light samples reach no light from a pass of 256
// or more that all added nothing; fewer leave what it knew, one lit
// sample says they do, and both halves of a split region keep the
// whole's.
TEST(GuidingTree, LearnsWhereLightSamplesReachNoLight) {
  GuidingTree tree(unit_box());
  GuidingRefinement settings;
  settings.spatial_threshold = 100;
  GuidingRegion& region = tree.region_at({0.2f, 0.5f, 0.5f});
  for (int i = 0; i < 256; ++i) region.guides[0].record_light_sample(false);
  for (int i = 0; i < 300; ++i) region.guides[1].record_light_sample(i == 123);
  for (int i = 0; i < 255; ++i) region.guides[2].record_light_sample(false);
  record(tree, {0.2f, 0.5f, 0.5f}, 150);
  tree.refine(settings, 1);
  ASSERT_EQ(tree.regions(), 2u);
  for (const Vec3 p : {Vec3{0.2f, 0.5f, 0.5f}, Vec3{0.8f, 0.5f, 0.5f}}) {
    EXPECT_TRUE(tree.region_at(p).guides[0].lights_unseen);
    EXPECT_FALSE(tree.region_at(p).guides[1].lights_unseen);
    EXPECT_FALSE(tree.region_at(p).guides[2].lights_unseen);
  }
  // A pass without light samples keeps it; a lit one among 256 undoes it.
  tree.refine(settings, 1);
  GuidingRegion& left = tree.region_at({0.2f, 0.5f, 0.5f});
  EXPECT_TRUE(left.guides[0].lights_unseen);
  for (int i = 0; i < 256; ++i) left.guides[0].record_light_sample(i == 0);
  tree.refine(settings, 1);
  EXPECT_FALSE(tree.region_at({0.2f, 0.5f, 0.5f}).guides[0].lights_unseen);
  EXPECT_TRUE(tree.region_at({0.8f, 0.5f, 0.5f}).guides[0].lights_unseen);
}

TEST(GuidingTree, PointsOutsideTheBoundsFallInTheNearestRegion) {
  GuidingTree tree(unit_box());
  GuidingRefinement settings;
  settings.spatial_threshold = 1;
  record(tree, {0.5f, 0.5f, 0.5f}, 10);
  tree.refine(settings, 1);
  EXPECT_EQ(&tree.region_at({-5, 0.5f, 0.5f}), &tree.region_at({0.01f, 0.5f, 0.5f}));
  EXPECT_EQ(&tree.region_at({7, 7, 7}), &tree.region_at({0.99f, 0.99f, 0.99f}));
  EXPECT_EQ(&tree.region_at({NAN, 0.5f, 0.5f}), &tree.region_at({0.01f, 0.5f, 0.5f}));
}

TEST(GuidingTree, TheMemoryCapStopsRefinementAndSaysSo) {
  GuidingTree tree(unit_box());
  GuidingRefinement settings;
  settings.spatial_threshold = 1;
  settings.max_bytes = tree.bytes() + 100;  // room for no second region
  record(tree, {0.5f, 0.5f, 0.5f}, 1000);
  tree.refine(settings, 1);
  EXPECT_EQ(tree.regions(), 1u);
  EXPECT_TRUE(tree.capped());
  EXPECT_LE(tree.bytes(), settings.max_bytes + 1000);
  settings.max_bytes = size_t(64) << 20;
  tree.refine(settings, 1);
  EXPECT_FALSE(tree.capped());
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
