#include "virtual_grid.h"

#include <flann/flann.hpp>

#include <algorithm>
#include <array>
#include <limits>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <unordered_set>

namespace sss {
namespace {

struct Layout {
  double spacing;
  Eigen::Vector3d origin;
  std::array<int, 3> dims;
};

// 2^level points along the longest side of the bounds (padded by the disc radius); the other
// axes get the same spacing and only as many points as they need (at least 2).
Layout layout_for(const LocalSurfels& surfels, int level) {
  const Eigen::Vector3d lo = surfels.bounds.min.array() - surfels.cell_radius;
  const Eigen::Vector3d extent =
      (surfels.bounds.max - surfels.bounds.min).array() + 2 * surfels.cell_radius;
  const int n = 1 << level;
  Layout layout;
  layout.spacing = extent.maxCoeff() / (n - 1);
  layout.origin = lo;
  for (int a = 0; a < 3; ++a)
    layout.dims[a] = std::clamp(static_cast<int>(std::ceil(extent[a] / layout.spacing)) + 1, 2, n);
  return layout;
}

// Corners of the cells that hold a surfel: the points the pruning will keep, counted cheaply
// to choose a level within the budget.
std::size_t occupied_corners(const LocalSurfels& surfels, const Layout& layout) {
  std::unordered_set<std::int64_t> corners;
  corners.reserve(surfels.size() * 2);
  const std::int64_t nx = layout.dims[0], ny = layout.dims[1];
  for (const auto& p : surfels.positions) {
    int cell[3];
    for (int a = 0; a < 3; ++a)
      cell[a] = std::clamp(static_cast<int>((p[a] - layout.origin[a]) / layout.spacing), 0,
                           layout.dims[a] - 2);
    for (int c = 0; c < 8; ++c)
      corners.insert(((cell[2] + (c >> 2)) * ny + cell[1] + ((c >> 1) & 1)) * nx + cell[0] +
                     (c & 1));
  }
  return corners.size();
}

}  // namespace

std::size_t VirtualGrid::dense_points(const LocalSurfels& surfels, int level) {
  const Layout layout = layout_for(surfels, level);
  return static_cast<std::size_t>(layout.dims[0]) * layout.dims[1] * layout.dims[2];
}

VirtualGrid VirtualGrid::build(const LocalSurfels& surfels, const Dipole& dipole,
                               const VirtualGridSettings& settings) {
  if (settings.max_level < 1 || settings.max_level > 16) {
    std::ostringstream msg;
    msg << "[sss::VirtualGrid] max_level = " << settings.max_level << " must be in [1, 16]";
    throw std::invalid_argument(msg.str());
  }
  int level = settings.level;
  if (level == 0) {
    double length = std::numeric_limits<double>::infinity();
    for (const auto& ch : dipole.channel) length = std::min(length, ch.diffusion_length());
    const double target = settings.spacing_in_diffusion_lengths * length;
    level = 1;
    while (level < settings.max_level) {
      const int next = level + 1;
      const Layout layout = layout_for(surfels, next);
      if (layout.spacing < target || dense_points(surfels, next) * 4 > settings.memory_cap_bytes ||
          occupied_corners(surfels, layout) > settings.point_budget)
        break;
      level = next;
    }
  }
  if (level < 1 || level > settings.max_level) {
    std::ostringstream msg;
    msg << "[sss::VirtualGrid] level = " << level << " must be in [1, " << settings.max_level
        << "] (2^level points per axis)";
    throw std::invalid_argument(msg.str());
  }
  VirtualGrid grid = prune(surfels, level, settings.memory_cap_bytes);
  // The corner count that chose an automatic level is a lower bound of what the radius search
  // keeps; step down until the budget holds.
  while (settings.level == 0 && grid.points_.size() > settings.point_budget && level > 1)
    grid = prune(surfels, --level, settings.memory_cap_bytes);
  return grid;
}

VirtualGrid VirtualGrid::prune(const LocalSurfels& surfels, int level, std::size_t memory_cap) {
  const std::size_t dense = dense_points(surfels, level);
  if (dense > std::numeric_limits<std::size_t>::max() / 4 ||
      dense * 4 > memory_cap) {
    std::ostringstream msg;
    msg << "[sss::VirtualGrid] level " << level << " (" << (1 << level)
        << " points per axis) needs " << dense * 4.0 / (1 << 20)
        << " MiB for its index; the cap is " << memory_cap / double(1 << 20)
        << " MiB";
    throw std::invalid_argument(msg.str());
  }
  const Layout layout = layout_for(surfels, level);
  VirtualGrid grid;
  grid.level_ = level;
  grid.spacing_ = layout.spacing;
  grid.origin_ = layout.origin;
  grid.dims_ = layout.dims;
  grid.index_.assign(dense, -1);
  if (surfels.size() == 0) return grid;

  std::vector<double> coords(surfels.size() * 3);
  for (std::size_t i = 0; i < surfels.size(); ++i)
    for (int a = 0; a < 3; ++a) coords[3 * i + a] = surfels.positions[i][a];
  flann::Matrix<double> data(coords.data(), surfels.size(), 3);
  flann::Index<flann::L2<double>> tree(data, flann::KDTreeSingleIndexParams(16));
  tree.buildIndex();
  const double radius = std::sqrt(3.0) * layout.spacing * (1.0 + 1e-9);  // one cell diagonal
  flann::SearchParams params;
  params.max_neighbors = 1;
  params.sorted = false;
  std::vector<std::uint8_t> keep(dense, 0);
  const std::int64_t total = static_cast<std::int64_t>(dense);
#pragma omp parallel default(none) shared(grid, tree, keep, total, radius, params)
  {
    std::vector<std::vector<std::size_t>> ids;
    std::vector<std::vector<double>> dist2;
    double query[3];
    flann::Matrix<double> q(query, 1, 3);
#pragma omp for schedule(dynamic, 4096)
    for (std::int64_t f = 0; f < total; ++f) {
      const int i = static_cast<int>(f % grid.dims_[0]);
      const int j = static_cast<int>((f / grid.dims_[0]) % grid.dims_[1]);
      const int k = static_cast<int>(f / (static_cast<std::int64_t>(grid.dims_[0]) * grid.dims_[1]));
      const Eigen::Vector3d p = grid.origin_ + grid.spacing_ * Eigen::Vector3d(i, j, k);
      query[0] = p.x();
      query[1] = p.y();
      query[2] = p.z();
      keep[f] = tree.radiusSearch(q, ids, dist2, static_cast<float>(radius * radius), params) > 0;
    }
  }
  for (std::int64_t f = 0; f < total; ++f) {
    if (!keep[f]) continue;
    const int i = static_cast<int>(f % grid.dims_[0]);
    const int j = static_cast<int>((f / grid.dims_[0]) % grid.dims_[1]);
    const int k = static_cast<int>(f / (static_cast<std::int64_t>(grid.dims_[0]) * grid.dims_[1]));
    grid.index_[f] = static_cast<std::int32_t>(grid.points_.size());
    grid.points_.push_back(grid.origin_ + grid.spacing_ * Eigen::Vector3d(i, j, k));
  }
  grid.anchors_.resize(grid.points_.size());
  const std::int64_t kept = static_cast<std::int64_t>(grid.points_.size());
#pragma omp parallel default(none) shared(grid, tree, surfels, kept)
  {
    std::vector<std::vector<std::size_t>> ids;
    std::vector<std::vector<double>> dist2;
    double query[3];
    flann::Matrix<double> q(query, 1, 3);
    flann::SearchParams nearest;
#pragma omp for schedule(dynamic, 1024)
    for (std::int64_t v = 0; v < kept; ++v) {
      const Eigen::Vector3d& p = grid.points_[v];
      for (int a = 0; a < 3; ++a) query[a] = p[a];
      tree.knnSearch(q, ids, dist2, 1, nearest);
      const std::size_t s = ids[0][0];
      const Eigen::Vector3d& n = surfels.normals[s];
      grid.anchors_[v] = p - n * n.dot(p - surfels.positions[s]);
    }
  }
  return grid;
}

bool VirtualGrid::interpolate(const std::vector<Rgb>& values, const Eigen::Vector3d& x,
                              Rgb& out) const {
  out = {0.0, 0.0, 0.0};
  if (points_.empty()) return false;
  int cell[3];
  double f[3];
  for (int a = 0; a < 3; ++a) {
    const double t = (x[a] - origin_[a]) / spacing_;
    cell[a] = std::clamp(static_cast<int>(std::floor(t)), 0, dims_[a] - 2);
    f[a] = std::clamp(t - cell[a], 0.0, 1.0);
  }
  double weight_sum = 0.0;
  for (int c = 0; c < 8; ++c) {
    const int di = c & 1, dj = (c >> 1) & 1, dk = c >> 2;
    const std::int32_t id = index_[flat(cell[0] + di, cell[1] + dj, cell[2] + dk)];
    if (id < 0) continue;
    const double w = (di ? f[0] : 1 - f[0]) * (dj ? f[1] : 1 - f[1]) * (dk ? f[2] : 1 - f[2]);
    for (int ch = 0; ch < 3; ++ch) out[ch] += w * values[id][ch];
    weight_sum += w;
  }
  if (!(weight_sum > 0.0)) return false;
  for (double& v : out) v /= weight_sum;
  return true;
}

}  // namespace sss
