// SlaveNodeShare's share of a pair's slave nodes over the ranks (solver/slave_node_share.hpp):
// even in cost, compact, the same on every rank. The share is computed without MPI (RankWorld
// only names the rank and the size), so it is checked here on one process for each rank's view.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "solver/slave_node_share.hpp"

namespace inpact::solver {
namespace {

std::vector<std::array<double, 3>> line_of_points(int n) {
  std::vector<std::array<double, 3>> points;
  for (int i = 0; i < n; ++i) points.push_back({static_cast<double>(i), 0.5, -1.0});
  return points;
}

TEST(SlaveNodeShare, EvenCostsGiveEqualCompactPatches) {
  const auto points = line_of_points(100);
  const std::vector<double> cost(points.size(), 1.0);
  for (int rank = 0; rank < 4; ++rank) {
    const SlaveNodeShare share(RankWorld{rank, 4}, points, cost);
    ASSERT_TRUE(share.shared());
    EXPECT_EQ(std::vector<long>(share.count_of_rank().begin(), share.count_of_rank().end()),
              (std::vector<long>{25, 25, 25, 25}));
    // Rank r holds the r-th quarter of the line: a patch.
    for (std::size_t i = 0; i < points.size(); ++i) EXPECT_EQ(share.owns(i), static_cast<int>(i / 25) == rank) << i;
  }
}

TEST(SlaveNodeShare, ANodeFacingTheMasterWeighsItsCost) {
  // Nodes 0..19 face the master (cost 20), the 80 others not (1): 480 in all, 240 per rank.
  const auto points = line_of_points(100);
  std::vector<double> cost(points.size(), 1.0);
  for (int i = 0; i < 20; ++i) cost[static_cast<std::size_t>(i)] = 20.0;
  const SlaveNodeShare share(RankWorld{0, 2}, points, cost);
  EXPECT_EQ(share.count_of_rank()[0], 12);  // 12 × 20 = 240
  EXPECT_EQ(share.count_of_rank()[1], 88);  // 8 × 20 + 80 = 240
}

TEST(SlaveNodeShare, EveryRankComputesTheSameShare) {
  // Ties along the cut (points at the same x) go by index, whatever rank computes them.
  std::vector<std::array<double, 3>> points;
  for (int i = 0; i < 60; ++i) points.push_back({static_cast<double>(i % 3), static_cast<double>(i / 3), 0.0});
  const std::vector<double> cost(points.size(), 1.0);
  const SlaveNodeShare a(RankWorld{0, 3}, points, cost), b(RankWorld{1, 3}, points, cost),
      c(RankWorld{2, 3}, points, cost);
  for (std::size_t i = 0; i < points.size(); ++i)
    EXPECT_EQ(a.owns(i) + b.owns(i) + c.owns(i), 1) << "node " << i << " is owned by exactly one rank";
  const std::vector<char> mask = b.owned_mask();
  for (std::size_t i = 0; i < points.size(); ++i) EXPECT_EQ(mask[i] != 0, b.owns(i));
  EXPECT_EQ(b.count_of_rank()[0] + b.count_of_rank()[1] + b.count_of_rank()[2], 60);
  for (long n : b.count_of_rank()) EXPECT_EQ(n, 20);
}

TEST(SlaveNodeShare, OneRankOwnsEveryNodeAndSharesNothing) {
  const auto points = line_of_points(5);
  const SlaveNodeShare share(RankWorld{0, 1}, points, std::vector<double>(5, 1.0));
  EXPECT_FALSE(share.shared());
  EXPECT_TRUE(share.owned_mask().empty());
  for (std::size_t i = 0; i < 5; ++i) EXPECT_TRUE(share.owns(i));
}

}  // namespace
}  // namespace inpact::solver
