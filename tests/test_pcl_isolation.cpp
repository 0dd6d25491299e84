// The PCL glue leaves isolated points out of the surfels (sssPclSurfels.h,
// core/surfels/isolated_points.h): a plane with a few strays off it keeps every plane point and
// none of the strays, says so in its summary, and keeps them all when asked to.
#include <gtest/gtest.h>
#include <pcl/point_types.h>
#include <vtkPolyData.h>

#include <random>

#include "sssPclSurfels.h"

namespace {

pcl::PointCloud<pcl::PointXYZ> plane_with_strays() {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> along(0.0f, 1.0f);
  for (int i = 0; i < 5000; ++i) cloud.push_back(pcl::PointXYZ(along(rng), along(rng), 0.0f));
  cloud.push_back(pcl::PointXYZ(0.5f, 0.5f, 0.4f));   // a return off the plane
  cloud.push_back(pcl::PointXYZ(0.2f, 0.9f, -0.3f));  // one behind it
  cloud.push_back(pcl::PointXYZ(3.0f, 0.5f, 0.0f));   // one far out in the plane
  return cloud;
}

TEST(PclIsolation, StraysAreLeftOutOfTheSurfels) {
  const pcl::PointCloud<pcl::PointXYZ> cloud = plane_with_strays();
  const sss::Surfels surfels = sss::makeSurfels(cloud);
  EXPECT_EQ(surfels.isolated_points, 3u);
  EXPECT_EQ(surfels.size(), 5000u);
  EXPECT_GT(surfels.largest_isolation, 5.0);
  double z_max = 0.0, x_max = 0.0;
  for (vtkIdType i = 0; i < surfels.polydata->GetNumberOfPoints(); ++i) {
    double p[3];
    surfels.polydata->GetPoint(i, p);
    z_max = std::max(z_max, std::abs(p[2]));
    x_max = std::max(x_max, p[0]);
  }
  EXPECT_EQ(z_max, 0.0);
  EXPECT_LE(x_max, 1.0);
  EXPECT_NE(surfels.summary().find("3 isolated dropped"), std::string::npos) << surfels.summary();
  // The mean spacing is the plane's, not pulled up by the strays: about 0.5 / sqrt(5000).
  EXPECT_NEAR(surfels.spacing, 0.5 / std::sqrt(5000.0), 0.2 * 0.5 / std::sqrt(5000.0));
}

TEST(PclIsolation, KeptWhenAskedAndBadSettingsRefused) {
  const pcl::PointCloud<pcl::PointXYZ> cloud = plane_with_strays();
  sss::SurfelOptions keep;
  keep.drop_isolated = false;
  const sss::Surfels all = sss::makeSurfels(cloud, keep);
  EXPECT_EQ(all.isolated_points, 0u);
  EXPECT_EQ(all.size() + all.points_without_normal, cloud.size());
  sss::SurfelOptions bad;
  bad.isolation_ratio = 0.5;
  EXPECT_THROW(sss::makeSurfels(cloud, bad), std::invalid_argument);
}

}  // namespace
