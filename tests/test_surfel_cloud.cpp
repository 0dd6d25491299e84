#include <gtest/gtest.h>

#include <limits>

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

}  // namespace
}  // namespace sss
