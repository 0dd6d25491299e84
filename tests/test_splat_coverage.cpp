// Splat radii from measured coverage (core/view/splat_coverage.h) against closed forms: a disc
// inside a square, the hexagonal lattice's covering radius, the void probability of a Poisson
// sampling, and a terrestrial scanner's rings, whose density falls with range.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sphere_cases.h"
#include "splat_coverage.h"
#include "surfel_index.h"

namespace sss {
namespace {
constexpr double kPi = 3.14159265358979323846;

SurfelCloud plane_cloud(const std::vector<Eigen::Vector3d>& points) {
  SurfelCloud cloud;
  cloud.positions = points;
  cloud.normals.assign(points.size(), Eigen::Vector3d::UnitZ());
  cloud.radius = 1.0;
  cloud.validate();
  return cloud;
}

SurfelCloud poisson_sphere(std::size_t n, unsigned seed) {
  SurfelCloud cloud;
  cloud.positions = test::random_unit_sphere(n, seed);
  cloud.normals = cloud.positions;
  cloud.radius = 1.0;
  cloud.validate();
  return cloud;
}

// A scanner 1 unit above the plane, stepping `step` radians in azimuth and in the angle from
// the vertical (20 to 70 degrees): rings whose spacing grows with range.
SurfelCloud scanner_rings(double step) {
  std::vector<Eigen::Vector3d> p;
  for (double a = 20.0 * kPi / 180.0; a < 70.0 * kPi / 180.0; a += step) {
    const double rho = std::tan(a);
    for (double phi = 0.0; phi < 2.0 * kPi - 0.5 * step; phi += step)
      p.emplace_back(rho * std::cos(phi), rho * std::sin(phi), 0.0);
  }
  return plane_cloud(p);
}

TEST(SplatCoverage, DiscInsideASquareHasItsClosedFormArea) {
  const Polygon square = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  EXPECT_NEAR(area_within(square, 0.5), kPi * 0.25, 1e-12);
  EXPECT_NEAR(area_within(square, 1.0), kPi, 1e-12);
  EXPECT_NEAR(area_within(square, std::sqrt(2.0)), 4.0, 1e-12);
  // r = 1.2: the disc less four caps of half-angle acos(1 / 1.2).
  const double r = 1.2, h = std::acos(1.0 / r);
  const double cap = r * r * (h - std::sin(h) * std::cos(h));
  EXPECT_NEAR(area_within(square, r), kPi * r * r - 4.0 * cap, 1e-12);
  // Off-centre: the unit square [0, 1]^2 within r = 1 of its corner is a quarter disc.
  const Polygon corner = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_NEAR(area_within(corner, 1.0), 0.25 * kPi, 1e-12);
}

TEST(SplatCoverage, HexagonalLatticeIsCoveredAtItsCircumradius) {
  std::vector<Eigen::Vector3d> p;
  const double a = 0.01;
  for (int row = 0; row < 60; ++row)
    for (int col = 0; col < 60; ++col)
      p.emplace_back(a * (col + 0.5 * (row % 2)), a * row * std::sqrt(3.0) / 2.0, 0.0);
  const SplatCoverage c = measure_splat_coverage(plane_cloud(p));
  ASSERT_GT(c.measured, 3000u);
  EXPECT_NEAR(c.radius_for(0.0), a / std::sqrt(3.0), 1e-6 * a);
  // Discs of half the spacing touch: they leave 1 - pi / (2 sqrt 3) of the plane open.
  EXPECT_NEAR(c.uncovered(0.5 * a), 1.0 - kPi / (2.0 * std::sqrt(3.0)), 1e-6);
  EXPECT_LT(c.spacing_spread, 1.05);
  const SplatRadii radii = choose_splat_radii(plane_cloud(p), SplatRadiusMode::Automatic);
  EXPECT_FALSE(radii.per_point_chosen());
  // The target leaves the corners' last slivers open: just under the circumradius.
  EXPECT_LE(radii.view_radius, a / std::sqrt(3.0));
  EXPECT_GT(radii.view_radius, 0.99 * a / std::sqrt(3.0));
  EXPECT_NEAR(radii.radius, kCellSpacings * a, 1e-9 * a);
}

TEST(SplatCoverage, PoissonSamplingMatchesItsVoidProbability) {
  // A point of the plane is farther than r from every sample of density rho with probability
  // exp(-rho pi r^2); the cells' measure is that fraction of the area.
  const std::size_t n = 20000;
  const SurfelCloud cloud = poisson_sphere(n, 7);
  const double rho = n / (4.0 * kPi);
  const SplatCoverage c = measure_splat_coverage(cloud);
  ASSERT_GT(c.measured, 19000u);
  for (double expected : {0.1, 1e-2, 1e-3}) {
    const double r = std::sqrt(std::log(1.0 / expected) / (kPi * rho));
    const double got = c.uncovered(r);
    std::printf("Poisson, r = %.4f: uncovered %.3g (closed form %.3g)\n", r, got, expected);
    EXPECT_NEAR(got / expected, 1.0, expected > 5e-3 ? 0.05 : 0.15);
  }
  const SplatRadii radii = choose_splat_radii(cloud, SplatRadiusMode::Automatic);
  const double closed = std::sqrt(std::log(1.0 / kDefaultCoverageTarget) / (kPi * rho));
  std::printf("Poisson: radius %.4f for %.0e uncovered (closed form %.4f), %.2f mean spacings, "
              "spacing spread %.2f\n",
              radii.view_radius, kDefaultCoverageTarget, closed, radii.view_radius / cloud.mean_spacing(),
              radii.spacing_spread);
  EXPECT_FALSE(radii.per_point_chosen());
  EXPECT_NEAR(radii.view_radius / closed, 1.0, 0.06);
}

TEST(SplatCoverage, ScannerRingsGetPerPointRadiiThatCloseEveryCell) {
  const SurfelCloud cloud = scanner_rings(0.004);
  const SplatRadii radii = choose_splat_radii(cloud, SplatRadiusMode::Automatic);
  // One radius for the whole scan would have to close its sparsest rings.
  const double uniform = measure_splat_coverage(cloud).radius_for(kDefaultCoverageTarget);
  std::printf("scanner rings: %zu points, spacing spread %.2f, uniform cover radius %.4f, light "
              "maps' %.4f\n",
              cloud.size(), radii.spacing_spread, uniform, radii.radius);
  EXPECT_NEAR(radii.radius, kCellSpacings * cloud.mean_spacing(), 1e-12);
  ASSERT_TRUE(radii.per_point_chosen());
  ASSERT_EQ(radii.per_point.size(), cloud.size());
  // Random points of the annulus between the first and last rings, away from its edges: each
  // lies within some surfel's own radius.
  const SurfelIndex index(cloud.positions);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double lo = std::tan(22.0 * kPi / 180.0), hi = std::tan(68.0 * kPi / 180.0);
  const double r_max = *std::max_element(radii.per_point.begin(), radii.per_point.end());
  std::vector<std::size_t> near;
  int uncovered = 0;
  const int trials = 20000;
  double mean_r2 = 0.0;
  for (double r : radii.per_point) mean_r2 += r * r / radii.per_point.size();
  for (int t = 0; t < trials; ++t) {
    const double rho = std::sqrt(lo * lo + u(rng) * (hi * hi - lo * lo)), phi = 2.0 * kPi * u(rng);
    const Eigen::Vector3d x(rho * std::cos(phi), rho * std::sin(phi), 0.0);
    index.within(x, r_max, near);
    bool covered = false;
    for (std::size_t j : near) covered = covered || (cloud.positions[j] - x).norm() <= radii.per_point[j];
    uncovered += covered ? 0 : 1;
  }
  std::printf("scanner rings: %d of %d random points uncovered by per-point radii; mean r^2 %.3g of "
              "the uniform cover radius's\n",
              uncovered, trials, mean_r2 / (uniform * uniform));
  EXPECT_EQ(uncovered, 0);
  EXPECT_LT(mean_r2, 0.5 * uniform * uniform);  // what per-point radii save
}

TEST(SplatCoverage, RefusesTargetsOutsideAFraction) {
  const SurfelCloud cloud = poisson_sphere(100, 1);
  EXPECT_THROW(choose_splat_radii(cloud, SplatRadiusMode::Uniform, 1.5), std::invalid_argument);
  EXPECT_THROW(choose_splat_radii(cloud, SplatRadiusMode::Uniform, 1e-4, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace sss
