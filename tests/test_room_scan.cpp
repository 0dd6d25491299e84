#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "room_scan.h"

namespace sss {
namespace {

// The distance of p from the nearest of the open room's five faces (m).
double off_faces(const Eigen::Vector3d& p) {
  return std::min({std::abs(p.x()), std::abs(kRoomSize[0] - p.x()), std::abs(p.y()),
                   std::abs(kRoomSize[1] - p.y()), std::abs(p.z())});
}

TEST(RoomScan, OpenRoomFromOneStationHasTheCountAskedForAndNoCeiling) {
  for (std::size_t count : {3000u, 100000u}) {
    const std::vector<Eigen::Vector3d> points = open_room_scan(count, 0.0, 1);
    EXPECT_NEAR(static_cast<double>(points.size()), static_cast<double>(count), 0.05 * count);
    double farthest = 0.0;
    for (const Eigen::Vector3d& p : points) {
      EXPECT_LT(p.z(), kRoomSize[2] - 0.009);
      farthest = std::max(farthest, off_faces(p));
    }
    EXPECT_LT(farthest, 1e-9) << "a noise-free ray ends on a face";
  }
}

// Uniform by area: each face's share of the points is its share of the area (floor 60 m^2 of
// 156), within four standard deviations of the binomial count.
TEST(RoomScan, UniformOpenRoomSharesThePointsByArea) {
  const std::size_t count = 40000;
  const std::vector<Eigen::Vector3d> points = uniform_open_room(count, 0.0, 3);
  ASSERT_EQ(points.size(), count);
  std::size_t floor = 0;
  for (const Eigen::Vector3d& p : points) {
    EXPECT_LT(off_faces(p), 1e-12);
    if (p.z() == 0.0) ++floor;
  }
  const double share = 60.0 / 156.0;
  EXPECT_NEAR(static_cast<double>(floor), share * count,
              4.0 * std::sqrt(share * (1.0 - share) * count));
}

}  // namespace
}  // namespace sss
