#include "core/render/pass_schedule.h"

#include <gtest/gtest.h>

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// The schedule written out by hand: 1, 2, 4, ... samples up to the cap.
TEST(PassSchedule, DoublesUpToTheCapThenStays) {
  const uint64_t firsts[] = {0, 1, 3, 7, 15, 31, 47};
  for (uint32_t pass = 0; pass + 1 < std::size(firsts); ++pass)
    for (uint64_t i = firsts[pass]; i < firsts[pass + 1]; ++i) {
      const Pass p = pass_containing(i, 16);
      EXPECT_EQ(p.number, pass) << i;
      EXPECT_EQ(p.first, firsts[pass]) << i;
      EXPECT_EQ(p.count, firsts[pass + 1] - firsts[pass]) << i;
    }
}

TEST(PassSchedule, CapsThatAreNotPowersOfTwoAndOne) {
  EXPECT_EQ(pass_containing(2, 3).count, 2u);
  EXPECT_EQ(pass_containing(3, 3).first, 3u);
  EXPECT_EQ(pass_containing(3, 3).count, 3u);
  EXPECT_EQ(pass_containing(7, 3).number, 3u);
  EXPECT_EQ(pass_containing(7, 3).first, 6u);
  for (uint64_t i : {0, 1, 5, 1000}) {
    EXPECT_EQ(pass_containing(i, 1).number, i);
    EXPECT_EQ(pass_containing(i, 1).count, 1u);
  }
  EXPECT_EQ(pass_containing(5, 0).count, 1u);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
