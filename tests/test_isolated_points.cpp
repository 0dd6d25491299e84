// Isolated points (core/surfels/isolated_points.h) on synthetic scans with known strays: a room's
// walls scanned from one station (density falling with the square of range, range noise) keep every
// surface point while single strays beside the walls, above the floor and between two surfaces are
// left out; a clean plane and a plane with Kinect-like depth noise lose nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "isolated_points.h"
#include "room_scan.h"

namespace sss {
namespace {
TEST(IsolatedPoints, RoomScanKeepsItsSurfaceAndLosesItsStrays) {
  std::vector<Eigen::Vector3d> points = room_scan(0.004, 0.003, 7);
  const std::size_t surface = points.size();
  // Strays: returns 0.5-1 m off a wall, a bird 1.2 m above the floor, a point in the air
  // between the ceiling and the floor, a pair 1.2 m off the far wall. Isolation is relative
  // to the spacing of the surface nearby: the same pair at (9.2, 1.5, 2.5), 0.5 m under the
  // far ceiling, which the station sees at grazing incidence (its points' mean distance to
  // their 16 nearest is 11 cm there, the pair's 48 cm), has a ratio of 4.4 and is kept.
  const std::vector<Eigen::Vector3d> strays{
    {9.0, 3.0, 1.0}, {5.0, 5.5, 2.0}, {0.5, 4.0, 0.7}, {7.0, 1.0, 1.2},
    {4.0, 4.0, 2.0}, {8.8, 4.5, 1.5}, {8.8, 4.52, 1.5}};
  points.insert(points.end(), strays.begin(), strays.end());
  IsolationReport report;
  const std::vector<bool> keep = find_surface_points(points, IsolationSettings{}, &report);
  std::size_t surface_lost = 0;
  for (std::size_t i = 0; i < surface; ++i) surface_lost += !keep[i];
  std::printf("[ room ] %zu surface points; %s; %zu surface points lost\n",
              surface, report.summary().c_str(), surface_lost);
  EXPECT_EQ(surface_lost, 0u);
  for (std::size_t k = 0; k < strays.size(); ++k)
    EXPECT_FALSE(keep[surface + k]) << "stray " << k << " kept: " << strays[k].transpose();
  EXPECT_EQ(report.isolated, strays.size());
  EXPECT_EQ(report.tested, points.size());
}

TEST(IsolatedPoints, NoisyRandomPlaneLosesNothing) {
  // A Kinect-like wall: 3.4 mm spacing at random, depth noise of one spacing.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> along(0.0, 0.6);
  std::normal_distribution<double> depth(0.0, 0.0034);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 30000; ++i) points.emplace_back(along(rng), along(rng), depth(rng));
  IsolationReport report;
  const std::vector<bool> keep = find_surface_points(points, IsolationSettings{}, &report);
  std::printf("[ noisy wall ] %s\n", report.summary().c_str());
  EXPECT_EQ(report.isolated, 0u) << report.summary();
  EXPECT_LT(report.largest_ratio, 3.0);
  EXPECT_EQ(std::count(keep.begin(), keep.end(), false), 0);
}

TEST(IsolatedPoints, DuplicatesAndSettings) {
  std::vector<Eigen::Vector3d> points(40, Eigen::Vector3d(1, 2, 3));  // one place, many times
  for (int i = 0; i < 40; ++i) points.emplace_back(0.01 * i, 0.0, 0.0);
  IsolationReport report;
  const std::vector<bool> keep = find_surface_points(points, IsolationSettings{}, &report);
  EXPECT_EQ(std::count(keep.begin(), keep.end(), false), 0) << report.summary();

  IsolationSettings off;
  off.enabled = false;
  const std::vector<Eigen::Vector3d> few{{0, 0, 0}, {100, 0, 0}};
  EXPECT_EQ(find_surface_points(few, off).size(), 2u);
  EXPECT_EQ(find_surface_points(few, IsolationSettings{}), std::vector<bool>(2, true));
  IsolationSettings bad;
  bad.ratio = 1.0;
  EXPECT_THROW(find_surface_points(points, bad), std::invalid_argument);
  bad = IsolationSettings{};
  bad.neighbours = 1;
  EXPECT_THROW(find_surface_points(points, bad), std::invalid_argument);
}

}  // namespace
}  // namespace sss
