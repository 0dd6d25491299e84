// How large the splats must be for the surface to read as closed. Each surfel's cell is its Voronoi
// cell among its nearest neighbours on the same surface, in its tangent plane; a disc covers its
// cell when it reaches the cell's farthest corner. A uniform radius r leaves uncovered the parts of
// the cells farther than r from their surfel, an area measured exactly (disc-polygon intersection);
// the uniform radius is the smallest one whose uncovered fraction meets a target. A cell ends where
// its neighbours do (their convex hull): at the edge of a scan, or of a hole wider than the
// neighbourhood, the surface ends, and the splats need not close it. A surfel whose 16 nearest
// neighbours leave its cell open is left out. Where the density varies (a scanner's thins with the
// square of range), one radius large enough for the sparse parts blurs the dense ones: then each
// surfel gets its own cell's reach.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "cell_polygon.h"
#include "surfel_cloud.h"

namespace sss {

enum class SplatRadiusMode { Automatic, Uniform, PerPoint };

struct SplatCoverage {
  std::size_t measured = 0;          // closed cells measured
  std::size_t open_edge = 0;         // of the measured surfels, those on an open edge
  std::vector<Polygon> cells;        // the measured closed cells, scene units, own frame
  double spacing_spread = 1.0;       // p90 / p10 of the local spacing (mean 16-neighbour distance)
  // Fraction of the measured cells' area farther than r from their surfel.
  double uncovered(double r) const;
  // The smallest r with uncovered(r) <= target.
  double radius_for(double target) const;
};

// Measures at most `max_cells` surfels spread evenly over the cloud (all when it holds fewer).
SplatCoverage measure_splat_coverage(const SurfelCloud& cloud, std::size_t max_cells = 20000);

// Each surfel's own cover radius (its cell's farthest corner, scene units); surfels on an
// open edge take the median of their closed neighbours'.
std::vector<double> per_point_cover_radii(const SurfelCloud& cloud);

// The splat radii a cloud gets. The view: where the spacing is even, the uniform radius that
// meets the coverage target; where it spreads (or a few large cells would set that radius, as
// the vertices of a mesh with a sparse patch), each surfel's own. The light maps draw the same
// discs, never under the cells' radius (no light leaks through gaps), and each cell reaches to
// its disc (the whole area its surfel stands for). The cells' radius, which scales the light
// maps' texels and the near field's reach, keeps kCellSpacings mean nearest-neighbour
// spacings: measured on the dragon sampled to 640,826 points, the coverage radius (3.4
// spacings) there grew the near table 5x.
struct SplatRadii {
  double radius = 0.0;            // the cells' (texels, near reach)
  double view_radius = 0.0;       // the view's (with per-point radii, their median)
  std::vector<double> per_point;  // empty: the view uses view_radius everywhere
  double view_uncovered = 0.0;    // measured uncovered fraction at view_radius (0 per point)
  double spacing_spread = 1.0;
  bool per_point_chosen() const { return !per_point.empty(); }
};

// Automatic picks per-point radii when the spacing spread exceeds kPerPointSpread, or when the
// uniform radius exceeds kPerPointTail times the one that leaves 5 % uncovered. `scale`
// multiplies the radii found; a target in (0, 1) is the uncovered area fraction allowed.
constexpr double kPerPointSpread = 1.6;
constexpr double kPerPointTail = 2.5;
constexpr double kCellSpacings = 1.5;
constexpr double kDefaultCoverageTarget = 1e-4;
SplatRadii choose_splat_radii(const SurfelCloud& cloud, SplatRadiusMode mode,
                              double coverage_target = kDefaultCoverageTarget, double scale = 1.0);

// Sets cloud.radius (the cells') and cloud.radii (the discs', one per surfel) from
// choose_splat_radii and returns what it found.
SplatRadii assign_splat_radii(SurfelCloud& cloud, SplatRadiusMode mode = SplatRadiusMode::Automatic,
                              double coverage_target = kDefaultCoverageTarget, double scale = 1.0);

// The area of polygon P within distance r of the origin.
double area_within(const Polygon& polygon, double r);

}  // namespace sss
