#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "local_surfels.h"
#include "procedural_shapes.h"
#include "surfel_cloud.h"

namespace sss {
namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

TEST(SurfelCloud, ValidationDropsAndReportsBadPoints) {
  SurfelCloud cloud;
  cloud.radius = 1.0;
  cloud.positions = {{0, 0, 0}, {kNaN, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, kInf, 0}, {4, 0, 0}, {5, 0, 0}};
  cloud.normals = {{0, 0, 1}, {0, 0, 1}, {0, kNaN, 1}, {0, 0, 0}, {0, 0, 1}, {0, 0, 3}, {1e-14, 0, 0}};
  const CloudReport report = cloud.validate();
  EXPECT_EQ(report.input, 7u);
  EXPECT_EQ(report.kept, 2u);
  EXPECT_EQ(report.nonfinite_position, 2u);
  EXPECT_EQ(report.nonfinite_normal, 1u);
  EXPECT_EQ(report.zero_normal, 2u);
  EXPECT_EQ(report.renormalised, 1u);
  ASSERT_EQ(cloud.size(), 2u);
  EXPECT_EQ(cloud.input_index, (std::vector<std::size_t>{0, 5}));
  EXPECT_DOUBLE_EQ(cloud.normals[1].z(), 1.0);
  EXPECT_NE(report.summary().find("kept 2 of 7"), std::string::npos);
}

TEST(SurfelCloud, RefusesBadRadiusSizesAndAlbedo) {
  SurfelCloud cloud;
  cloud.positions = {{0, 0, 0}};
  cloud.normals = {{0, 0, 1}};
  cloud.radius = 0.0;
  EXPECT_THROW(cloud.validate(), std::invalid_argument);
  cloud.radius = kNaN;
  EXPECT_THROW(cloud.validate(), std::invalid_argument);
  cloud.radius = 1.0;
  cloud.albedo = {{0.5, 0.5, 1.5}};
  EXPECT_THROW(cloud.validate(), std::invalid_argument);
  cloud.albedo = {{0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}};
  EXPECT_THROW(cloud.validate(), std::invalid_argument);
  cloud.albedo.clear();
  cloud.normals.clear();
  EXPECT_THROW(cloud.validate(), std::invalid_argument);
}

TEST(SurfelCloud, EmptyCloudIsValid) {
  SurfelCloud cloud;
  const CloudReport report = cloud.validate();
  EXPECT_EQ(report.kept, 0u);
  EXPECT_TRUE(cloud.bounds().empty);
  EXPECT_EQ(cloud.mean_spacing(), 0.0);
}

TEST(SurfelCloud, MeanSpacingOfAGridIsItsSpacing) {
  const SurfelCloud slab = make_slab(10.0, 0.5);
  EXPECT_NEAR(slab.mean_spacing(), 0.5, 1e-9);
}

TEST(SurfelCloud, DuplicatesDoNotHideTheSpacing) {
  SurfelCloud slab = make_slab(5.0, 0.5);
  const std::size_t n = slab.size();
  for (std::size_t i = 0; i < n; ++i) {
    slab.positions.push_back(slab.positions[i]);
    slab.normals.push_back(slab.normals[i]);
  }
  EXPECT_NEAR(slab.mean_spacing(), 0.5, 1e-9);
}

// A patch at UTM-like coordinates and the same patch moved by whole metres to near the origin
// (the move itself inexact in the centre: 0.5 (min + max) rounds): the local frames'
// coordinates agree bit for bit.
TEST(SurfelCloud, MovingByWholeUnitsKeepsLocalCoordinatesExactly) {
  SurfelCloud utm = make_slab(37.3, 0.61);
  const Eigen::Vector3d offset(512600.0, 5403579.0, 350.0);
  const Eigen::Vector3d fraction(0.0123456789, 0.3179, 0.0701);
  for (Eigen::Vector3d& p : utm.positions) p += offset + fraction;
  // One point a unit in the last place beyond the maximum where min + max is exact, so that
  // the centre rounds in every coordinate.
  const auto sum_is_exact = [](const Bounds& b, int k) {
    return (b.min[k] + b.max[k]) - b.max[k] == b.min[k];
  };
  const Bounds before = utm.bounds();
  Eigen::Vector3d beyond = before.max;
  for (int k = 0; k < 3; ++k)
    if (sum_is_exact(before, k)) beyond[k] = std::nextafter(before.max[k], 2.0 * before.max[k]);
  utm.positions.push_back(beyond);
  utm.normals.push_back(utm.normals.back());
  const Bounds after = utm.bounds();
  for (int k = 0; k < 3; ++k) ASSERT_FALSE(sum_is_exact(after, k)) << "coordinate " << k;
  SurfelCloud moved = utm;
  for (Eigen::Vector3d& p : moved.positions) p -= offset;
  const LocalSurfels a = LocalSurfels::from(utm, 1000.0, false);
  const LocalSurfels b = LocalSurfels::from(moved, 1000.0, false);
  ASSERT_EQ(a.positions.size(), b.positions.size());
  for (std::size_t i = 0; i < a.positions.size(); ++i)
    ASSERT_EQ(a.positions[i], b.positions[i]) << "point " << i;
  // The origin stays within a 4096th of the extent of the centre.
  EXPECT_LE((a.frame.origin - after.center()).cwiseAbs().maxCoeff(), 37.3 / 4096.0);
}

}  // namespace
}  // namespace sss
