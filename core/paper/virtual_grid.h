// The paper's virtual points: a regular grid of 2^k points per axis over the surfels' bounds,
// pruned to the points with surface within one cell diagonal (FLANN radius search), so that
// every surfel finds all 8 corners of its cell.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "dipole.h"
#include "local_surfels.h"

namespace sss {

struct VirtualGridSettings {
  int level = 0;  // 2^level points per axis; 0 chooses it (below)
  // Auto: the finest level whose spacing is at least this many diffusion lengths (1/s_tr of
  // the channel that decays fastest) and that keeps at most point_budget points.
  double spacing_in_diffusion_lengths = 0.5;
  std::size_t point_budget = 65536;
  int max_level = 10;
  // A level whose dense index (4 bytes per grid point) would exceed this is refused.
  std::size_t memory_cap_bytes = std::size_t(1) << 30;
};

class VirtualGrid {
 public:
  // Throws std::invalid_argument for a level outside [1, max_level] or one over the memory cap.
  static VirtualGrid build(const LocalSurfels& surfels, const Dipole& dipole,
                           const VirtualGridSettings& settings);

  int level() const { return level_; }
  double spacing() const { return spacing_; }
  const std::array<int, 3>& dims() const { return dims_; }
  const Eigen::Vector3d& origin() const { return origin_; }  // first grid point, local mm
  const std::vector<Eigen::Vector3d>& points() const { return points_; }  // kept, local mm
  // Where B is evaluated for each kept point: the point moved along the normal of its nearest
  // surfel onto that surfel's tangent plane, so that the value interpolated between the
  // corners is one of the surface, not of the space a cell's width above or below it.
  const std::vector<Eigen::Vector3d>& anchors() const { return anchors_; }

  // Trilinear interpolation of per-kept-point values at x; corners that were pruned are left
  // out and the weights renormalised. Returns false when no corner was kept.
  bool interpolate(const std::vector<Rgb>& values, const Eigen::Vector3d& x, Rgb& out) const;

  // Grid points (before pruning) at a level, and the memory their dense index needs.
  static std::size_t dense_points(const LocalSurfels& surfels, int level);

 private:
  // The grid at `level` with the points that have a surfel within one cell diagonal.
  static VirtualGrid prune(const LocalSurfels& surfels, int level, std::size_t memory_cap);
  std::int64_t flat(int i, int j, int k) const {
    return (static_cast<std::int64_t>(k) * dims_[1] + j) * dims_[0] + i;
  }
  int level_ = 0;
  double spacing_ = 0.0;
  Eigen::Vector3d origin_{Eigen::Vector3d::Zero()};
  std::array<int, 3> dims_{{0, 0, 0}};
  std::vector<std::int32_t> index_;  // dense: kept-point id or -1
  std::vector<Eigen::Vector3d> points_;
  std::vector<Eigen::Vector3d> anchors_;
};

}  // namespace sss
