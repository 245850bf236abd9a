#include "core/job/sample_ranges.h"

#include <gtest/gtest.h>

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// Out of order, touching, empty and apart: sorted, joined where they touch,
// empty ones gone, listed inclusively.
TEST(SampleRanges, JoinTouchingRangesAndListThemInclusively) {
  const std::vector<IndexRange> joined = joined_ranges({{10, 5}, {0, 3}, {7, 0}, {3, 2}, {15, 1}, {20, 4}});
  ASSERT_EQ(joined.size(), 3u);
  EXPECT_EQ(format_ranges(joined), "0-4,10-15,20-23");
  EXPECT_EQ(format_ranges(joined_ranges({})), "");
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
