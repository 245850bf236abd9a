#include "core/job/rank_shares.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// The shares cover the range exactly, in rank order, without overlap, and
// differ in size by at most one, for ranges smaller and larger than the
// number of ranks.
TEST(RankShares, CutARangeIntoContiguousPiecesInRankOrder) {
  for (int ranks = 1; ranks <= 7; ++ranks)
    for (uint64_t count : {0u, 1u, 2u, 5u, 16u, 17u, 100u})
      for (uint64_t round = 0; round < 9; ++round) {
        uint64_t next = 1000, smallest = count, largest = 0;
        for (int r = 0; r < ranks; ++r) {
          const IndexRange share = rank_share({1000, count}, r, ranks, round);
          EXPECT_EQ(share.first, next) << ranks << " ranks, " << count << " samples, rank " << r;
          next += share.count;
          smallest = std::min(smallest, share.count);
          largest = std::max(largest, share.count);
        }
        EXPECT_EQ(next, 1000 + count);
        EXPECT_LE(largest - std::min(smallest, largest), 1u);
      }
}

// 16 samples among 3 ranks is 6, 5, 5: the 6 moves from rank to rank with
// the round, so three rounds give each rank 16.
TEST(RankShares, TheLargerSharesRotateWithTheRound) {
  for (int ranks : {3, 5}) {
    std::vector<uint64_t> total(size_t(ranks), 0);
    for (uint64_t round = 7; round < 7 + uint64_t(ranks); ++round)
      for (int r = 0; r < ranks; ++r) total[size_t(r)] += rank_share({0, 16}, r, ranks, round).count;
    for (uint64_t t : total) EXPECT_EQ(t, 16u) << ranks << " ranks";
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
