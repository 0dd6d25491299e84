#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <vector>

#include "hilbert_order.h"

namespace sss {
namespace {

// The curve visits every cell of an aligned 8 x 8 x 8 block in one run of 512 indices, each
// step to a cell that shares a face with the one before.
TEST(HilbertOrder, StepsOnlyBetweenFaceNeighboursAndFillsAlignedBlocks) {
  const double cell = 1.0 / (1 << 21);  // the curve's cells over the unit cube
  for (const Eigen::Vector3i& corner : {Eigen::Vector3i(0, 0, 0), Eigen::Vector3i(8, 16, 40)}) {
    std::vector<std::pair<std::uint64_t, Eigen::Vector3i>> cells;
    for (int x = 0; x < 8; ++x)
      for (int y = 0; y < 8; ++y)
        for (int z = 0; z < 8; ++z) {
          const Eigen::Vector3i c = corner + Eigen::Vector3i(x, y, z);
          cells.push_back({hilbert_index((c.cast<double>() + Eigen::Vector3d::Constant(0.5)) * cell,
                                         Eigen::Vector3d::Zero(), 1.0),
                           c});
        }
    std::sort(cells.begin(), cells.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    EXPECT_EQ(cells.back().first - cells.front().first, 511u);
    EXPECT_EQ(cells.front().first % 512, 0u);
    for (std::size_t k = 1; k < cells.size(); ++k) {
      EXPECT_EQ((cells[k].second - cells[k - 1].second).cwiseAbs().sum(), 1) << "step " << k;
    }
  }
}

TEST(HilbertOrder, OrdersAPermutationAndKeepsTiesInInputOrder) {
  const std::vector<Eigen::Vector3d> points = {
      {0, 0, 0}, {1, 1, 1}, {0, 0, 0}, {0.5, 0.5, 0.5}, {1, 1, 1}, {0, 0, 0}};
  const std::vector<std::size_t> order = hilbert_order(points);
  ASSERT_EQ(order.size(), points.size());
  std::vector<std::size_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(sorted, (std::vector<std::size_t>{0, 1, 2, 3, 4, 5}));
  // The three points at the origin (index 0 of the curve) first, in input order.
  EXPECT_EQ(order[0], 0u);
  EXPECT_EQ(order[1], 2u);
  EXPECT_EQ(order[2], 5u);
  EXPECT_TRUE(hilbert_order({}).empty());
}

}  // namespace
}  // namespace sss
