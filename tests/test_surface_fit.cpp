// The local surface fit against shapes whose curvature and roughness are known: a sphere
// (kappa = 1 / R, sigma = 0), a thin plate whose two sheets are closer than the spacing,
// a flat sheet with flipped normals, and a plane with Gaussian depth noise.
#include <gtest/gtest.h>

#include "surface_fit.h"

#include <cmath>
#include <random>

namespace sss {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A square grid of n x n points `spacing` apart in the plane z = height.
void add_sheet(int n, double spacing, double height, const Eigen::Vector3d& normal,
               std::vector<Eigen::Vector3d>& positions, std::vector<Eigen::Vector3d>& normals) {
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      positions.emplace_back(i * spacing, j * spacing, height);
      normals.push_back(normal);
    }
}

// Points far enough from the sheet's border to have a full neighbourhood.
bool interior(const Eigen::Vector3d& p, int n, double spacing) {
  const double lo = 4 * spacing, hi = (n - 5) * spacing;
  return p.x() > lo && p.x() < hi && p.y() > lo && p.y() < hi;
}

TEST(SurfaceFit, SphereHasCurvatureOneOverRadiusAndNoRoughness) {
  const double radius = 3.0;
  const int count = 20000;  // about 75 mm apart on a 3 m sphere
  std::vector<Eigen::Vector3d> positions, normals;
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / count, r = std::sqrt(1.0 - z * z);
    const Eigen::Vector3d n(r * std::cos(golden * i), r * std::sin(golden * i), z);
    positions.push_back(radius * n);
    normals.push_back(n);
  }
  const SurfaceFit fit = fit_local_surfaces(positions, normals);
  double worst_kappa = 0.0, worst_sigma = 0.0;
  for (int i = 0; i < count; ++i) {
    worst_kappa = std::max(worst_kappa, std::fabs(fit.curvature[i] * radius - 1.0));
    worst_sigma = std::max(worst_sigma, fit.roughness[i]);
  }
  // The paraboloid departs from the sphere by |d|^4 / (8 R^3): microns at these offsets.
  EXPECT_LT(worst_kappa, 1e-3);
  EXPECT_LT(worst_sigma, 1e-5 * radius);
}

TEST(SurfaceFit, ThinPlateIsTwoFlatSheetsNotOneRoughOne) {
  const int n = 30;
  const double spacing = 1.0, thickness = 0.3;  // the other sheet is nearer than the spacing
  std::vector<Eigen::Vector3d> positions, normals;
  add_sheet(n, spacing, 0.0, Eigen::Vector3d::UnitZ(), positions, normals);
  add_sheet(n, spacing, -thickness, -Eigen::Vector3d::UnitZ(), positions, normals);
  const SurfaceFit fit = fit_local_surfaces(positions, normals);
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (!interior(positions[i], n, spacing)) continue;
    EXPECT_NEAR(fit.curvature[i], 0.0, 1e-12) << i;
    EXPECT_NEAR(fit.roughness[i], 0.0, 1e-12) << i;
  }
}

TEST(SurfaceFit, FlippedNormalsOnOneSheetDoNotMatter) {
  const int n = 30;
  const double spacing = 1.0;
  std::vector<Eigen::Vector3d> positions, normals;
  add_sheet(n, spacing, 0.0, Eigen::Vector3d::UnitZ(), positions, normals);
  for (std::size_t i = 0; i < normals.size(); i += 3) normals[i] = -normals[i];
  const SurfaceFit fit = fit_local_surfaces(positions, normals);
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (!interior(positions[i], n, spacing)) continue;
    EXPECT_NEAR(fit.curvature[i], 0.0, 1e-12) << i;
    EXPECT_NEAR(fit.roughness[i], 0.0, 1e-12) << i;
  }
}

TEST(SurfaceFit, RoughnessOfANoisyPlaneIsTheNoiseOfAHeightDifference) {
  const int n = 120;
  const double spacing = 1.0, noise = 0.05;
  std::vector<Eigen::Vector3d> positions, normals;
  add_sheet(n, spacing, 0.0, Eigen::Vector3d::UnitZ(), positions, normals);
  std::mt19937 random(7);
  std::normal_distribution<double> depth(0.0, noise);
  for (auto& p : positions) p.z() = depth(random);
  // 12 neighbours are the grid's first three rings whole: a count that cut a ring would pick
  // the neighbours nearest in height and bias the figure low.
  const SurfaceFit fit = fit_local_surfaces(positions, normals, 12);
  double sum2 = 0.0;
  int count = 0;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (!interior(positions[i], n, spacing)) continue;
    EXPECT_NEAR(fit.curvature[i], 0.0, 1e-12);  // exact normals do not turn
    sum2 += fit.roughness[i] * fit.roughness[i];
    ++count;
  }
  // E[(h_j - h_i)^2] = 2 noise^2; 12k points give the mean to about 1 %.
  EXPECT_NEAR(std::sqrt(sum2 / count), std::sqrt(2.0) * noise, 0.03 * noise);
}

TEST(SurfaceFit, RefusesMismatchedSizes) {
  EXPECT_THROW(fit_local_surfaces({Eigen::Vector3d::Zero()}, {}), std::invalid_argument);
  EXPECT_THROW(fit_local_surfaces({}, {}, 0), std::invalid_argument);
}

}  // namespace
}  // namespace sss
