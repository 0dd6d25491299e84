#include <gtest/gtest.h>

#include "local_surfels.h"
#include "procedural_shapes.h"
#include "virtual_grid.h"

namespace sss {
namespace {

const Dipole kMarble{Material::preset("marble")};

VirtualGridSettings level(int k) {
  VirtualGridSettings s;
  s.level = k;
  return s;
}

// Trilinear interpolation reproduces a linear field exactly when all 8 corners are present.
void expect_all_corners_kept(const LocalSurfels& surfels, const VirtualGrid& grid) {
  auto field = [](const Eigen::Vector3d& x) { return Rgb{1 + 0.1 * x.x(), 2 - 0.2 * x.y(), 0.3 * x.z()}; };
  std::vector<Rgb> values;
  for (const auto& p : grid.points()) values.push_back(field(p));
  for (const auto& x : surfels.positions) {
    Rgb v;
    ASSERT_TRUE(grid.interpolate(values, x, v));
    const Rgb expected = field(x);
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(v[c], expected[c], 1e-9);
  }
}

TEST(VirtualGrid, PrunedToTheSurfaceAndEveryCellComplete) {
  const LocalSurfels torus = LocalSurfels::from(make_torus(20, 5, 0.5), 1.0);
  const VirtualGrid grid = VirtualGrid::build(torus, kMarble, level(6));
  expect_all_corners_kept(torus, grid);
  // Exactly the grid points with a surfel within one cell diagonal are kept (brute force).
  const double radius = std::sqrt(3.0) * grid.spacing();
  std::size_t near_surface = 0, dense = 0;
  for (int k = 0; k < grid.dims()[2]; ++k)
    for (int j = 0; j < grid.dims()[1]; ++j)
      for (int i = 0; i < grid.dims()[0]; ++i) {
        const Eigen::Vector3d p = grid.origin() + grid.spacing() * Eigen::Vector3d(i, j, k);
        ++dense;
        for (const auto& x : torus.positions)
          if ((x - p).norm() <= radius) {
            ++near_surface;
            break;
          }
      }
  EXPECT_EQ(grid.points().size(), near_surface);
  EXPECT_LT(grid.points().size(), dense / 2);
}

// Each kept point's anchor is the point moved along its nearest surfel's normal onto that
// surfel's tangent plane: on a sphere, it lies on the surface to within the facet's sag
// (h^2 / 2R for a surfel h away), and it keeps the point's direction from the centre.
TEST(VirtualGrid, AnchorsLieOnTheSurfaceBelowTheirPoints) {
  const double r = 50.0;
  const LocalSurfels sphere = LocalSurfels::from(make_sphere(r, 0.5), 1.0);
  const VirtualGrid grid = VirtualGrid::build(sphere, kMarble, level(5));
  ASSERT_EQ(grid.anchors().size(), grid.points().size());
  const Eigen::Vector3d centre = sphere.bounds.center();
  double worst_radius = 0.0, worst_direction = 1.0, largest_move = 0.0;
  for (std::size_t i = 0; i < grid.points().size(); ++i) {
    const Eigen::Vector3d p = grid.points()[i] - centre, a = grid.anchors()[i] - centre;
    worst_radius = std::max(worst_radius, std::abs(a.norm() - r));
    worst_direction = std::min(worst_direction, a.normalized().dot(p.normalized()));
    largest_move = std::max(largest_move, (a - p).norm());
  }
  // Spacing 0.5 mm: the nearest surfel is within ~0.35 mm laterally, a sag under 0.01 mm.
  EXPECT_LT(worst_radius, 0.01);
  EXPECT_GT(worst_direction, 0.9999);
  // Kept points lie within one cell diagonal of the surface, so no anchor moves further.
  EXPECT_LE(largest_move, std::sqrt(3.0) * grid.spacing() + 1e-9);
  EXPECT_GT(largest_move, 0.5 * grid.spacing());
}

TEST(VirtualGrid, AutomaticLevelFollowsDiffusionLengthAndBudget) {
  const LocalSurfels sphere = LocalSurfels::from(make_sphere(50, 1.0), 1.0);
  VirtualGridSettings s;
  const VirtualGrid grid = VirtualGrid::build(sphere, kMarble, s);
  double shortest = 1e300;
  for (const auto& ch : kMarble.channel) shortest = std::min(shortest, ch.diffusion_length());
  EXPECT_GE(grid.spacing(), s.spacing_in_diffusion_lengths * shortest);
  EXPECT_LE(grid.points().size(), s.point_budget);
  s.point_budget = 2000;
  const VirtualGrid small = VirtualGrid::build(sphere, kMarble, s);
  EXPECT_LE(small.points().size(), 2000u);
  EXPECT_LT(small.level(), grid.level());
  expect_all_corners_kept(sphere, small);
}

TEST(VirtualGrid, PlanarAndLineClouds) {
  const LocalSurfels slab = LocalSurfels::from(make_slab(10, 0.5), 1.0);
  const VirtualGrid flat = VirtualGrid::build(slab, kMarble, level(4));
  EXPECT_EQ(flat.dims()[2], 2);
  expect_all_corners_kept(slab, flat);
  const LocalSurfels local = LocalSurfels::from(make_line(50, 0.3), 1.0);
  const VirtualGrid thin = VirtualGrid::build(local, kMarble, level(4));
  EXPECT_EQ(thin.dims()[1], 2);
  EXPECT_EQ(thin.dims()[2], 2);
  expect_all_corners_kept(local, thin);
}

TEST(VirtualGrid, HugeRequestsAreRefusedClearly) {
  const LocalSurfels sphere = LocalSurfels::from(make_sphere(10, 1.0), 1.0);
  try {
    VirtualGridSettings s = level(11);
    s.max_level = 16;
    VirtualGrid::build(sphere, kMarble, s);
    FAIL() << "a 2048^3 grid was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("MiB"), std::string::npos) << e.what();
  }
  EXPECT_THROW(VirtualGrid::build(sphere, kMarble, level(17)), std::invalid_argument);
  EXPECT_THROW(VirtualGrid::build(sphere, kMarble, level(-1)), std::invalid_argument);
}

TEST(VirtualGrid, EmptyCloud) {
  const LocalSurfels empty = LocalSurfels::from(SurfelCloud{}, 1.0);
  const VirtualGrid grid = VirtualGrid::build(empty, kMarble, level(3));
  EXPECT_TRUE(grid.points().empty());
  Rgb v;
  EXPECT_FALSE(grid.interpolate({}, Eigen::Vector3d::Zero(), v));
}

}  // namespace
}  // namespace sss
