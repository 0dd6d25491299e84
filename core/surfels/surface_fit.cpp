#include "surface_fit.h"

#include <flann/flann.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sss {
namespace {

// A neighbour at offset d facing away from n_i and off n_i's tangent plane by more than
// about 11 degrees lies on the other side of a thin part, not on a flipped normal of the
// same sheet (whose offset is tangential).
bool on_the_other_sheet(const Eigen::Vector3d& d, const Eigen::Vector3d& ni,
                        const Eigen::Vector3d& nj) {
  return nj.dot(ni) < 0.0 && std::fabs(d.dot(ni)) > 0.2 * d.norm();
}

}  // namespace

SurfaceFit fit_local_surfaces(const std::vector<Eigen::Vector3d>& positions,
                              const std::vector<Eigen::Vector3d>& normals, int neighbours) {
  if (neighbours < 1)
    throw std::invalid_argument("[sss::fit_local_surfaces] neighbours must be >= 1");
  if (normals.size() != positions.size())
    throw std::invalid_argument("[sss::fit_local_surfaces] one normal per position is needed");
  const std::size_t n = positions.size();
  SurfaceFit fit;
  fit.curvature.assign(n, 0.0);
  fit.roughness.assign(n, 0.0);
  if (n < 2) return fit;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  for (const auto& p : positions) origin += p / static_cast<double>(n);
  std::vector<double> coords(3 * n);
  for (std::size_t i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a) coords[3 * i + a] = positions[i][a] - origin[a];
  flann::Matrix<double> data(coords.data(), n, 3);
  flann::Index<flann::L2<double>> index(data, flann::KDTreeSingleIndexParams(16));
  index.buildIndex();
  const int k = static_cast<int>(std::min<std::size_t>(n, static_cast<std::size_t>(neighbours) + 1));
  const long count = static_cast<long>(n);
#pragma omp parallel default(none) shared(index, coords, positions, normals, fit, k, count)
  {
    std::vector<std::vector<std::size_t>> ids;
    std::vector<std::vector<double>> dist2;
    flann::SearchParams params;
#pragma omp for schedule(dynamic, 1024)
    for (long i = 0; i < count; ++i) {
      flann::Matrix<double> query(&coords[3 * i], 1, 3);
      index.knnSearch(query, ids, dist2, k, params);
      const Eigen::Vector3d& p = positions[i];
      const Eigen::Vector3d& ni = normals[i];
      std::vector<std::size_t>& same = ids[0];
      same.erase(std::remove_if(same.begin(), same.end(),
                                [&](std::size_t j) {
                                  const Eigen::Vector3d d = positions[j] - p;
                                  return !(d.squaredNorm() > 0.0) ||
                                         on_the_other_sheet(d, ni, normals[j]);
                                }),
                 same.end());
      double turn = 0.0, spread = 0.0;
      for (std::size_t j : same) {
        const Eigen::Vector3d d = positions[j] - p;
        const Eigen::Vector3d nj = normals[j].dot(ni) < 0.0 ? Eigen::Vector3d(-normals[j]) : normals[j];
        turn += (nj - ni).dot(d);
        spread += d.squaredNorm();
      }
      const double kappa = spread > 0.0 ? turn / spread : 0.0;
      double height2 = 0.0;
      int heights = 0;
      for (std::size_t j : same) {
        const Eigen::Vector3d d = positions[j] - p;
        const double along = d.dot(ni);
        const double tangential2 = d.squaredNorm() - along * along;
        const double h = along + 0.5 * kappa * tangential2;
        height2 += h * h;
        ++heights;
      }
      fit.curvature[i] = kappa;
      fit.roughness[i] = heights > 0 ? std::sqrt(height2 / heights) : 0.0;
    }
  }
  return fit;
}

}  // namespace sss
