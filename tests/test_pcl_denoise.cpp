// The PCL glue puts a noisy scan's points on the surface they measured (sssPclSurfels.h,
// core/surfels/denoised_surface.h): a plane with Gaussian depth noise comes back flat, with the
// noise it carried measured per point in a "Noise" array and summarised; off, the points stay.
#include <gtest/gtest.h>
#include <pcl/point_types.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "sssPclSurfels.h"

namespace {

constexpr float kNoise = 0.004f;  // 4 mm at points 1 cm apart (scene units: metres)

pcl::PointCloud<pcl::PointXYZ> noisy_plane() {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  std::mt19937 rng(21);
  std::uniform_real_distribution<float> along(0.0f, 1.0f);
  std::normal_distribution<float> depth(0.0f, kNoise);
  for (int i = 0; i < 10000; ++i) cloud.push_back(pcl::PointXYZ(along(rng), along(rng), depth(rng)));
  return cloud;
}

// RMS height over the points 0.2 from the plane's edges.
double inner_height_rms(vtkPolyData* polydata) {
  double sum = 0.0;
  int count = 0;
  for (vtkIdType i = 0; i < polydata->GetNumberOfPoints(); ++i) {
    double p[3];
    polydata->GetPoint(i, p);
    if (std::min({p[0], 1.0 - p[0], p[1], 1.0 - p[1]}) < 0.2) continue;
    sum += p[2] * p[2];
    ++count;
  }
  return std::sqrt(sum / count);
}

TEST(PclDenoise, NoisyPlaneComesBackFlatWithItsNoiseMeasured) {
  const sss::Surfels surfels = sss::makeSurfels(noisy_plane());
  ASSERT_TRUE(surfels.denoised);
  EXPECT_EQ(surfels.size(), 10000u);
  EXPECT_NEAR(surfels.noise_median, kNoise, 0.15 * kNoise);
  EXPECT_LT(inner_height_rms(surfels.polydata), 0.5 * kNoise);
  vtkDataArray* noise = surfels.polydata->GetPointData()->GetArray("Noise");
  ASSERT_NE(noise, nullptr);
  ASSERT_EQ(noise->GetNumberOfTuples(), 10000);
  std::vector<double> values(10000);
  for (vtkIdType i = 0; i < 10000; ++i) values[i] = noise->GetTuple1(i);
  std::nth_element(values.begin(), values.begin() + 5000, values.end());
  EXPECT_NEAR(values[5000], kNoise, 0.15 * kNoise);
  EXPECT_NE(surfels.summary().find("on the measured surface (noise"), std::string::npos)
    << surfels.summary();
}

TEST(PclDenoise, OffKeepsThePointsWhereTheyAre) {
  sss::SurfelOptions options;
  options.denoise = false;
  const sss::Surfels surfels = sss::makeSurfels(noisy_plane(), options);
  EXPECT_FALSE(surfels.denoised);
  EXPECT_NEAR(inner_height_rms(surfels.polydata), kNoise, 0.1 * kNoise);
  EXPECT_EQ(surfels.polydata->GetPointData()->GetArray("Noise"), nullptr);
}

}  // namespace
