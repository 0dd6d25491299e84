#include "surfel_index.h"

#include <flann/flann.hpp>

namespace sss {

struct SurfelIndex::Impl {
  Eigen::Vector3d origin{Eigen::Vector3d::Zero()};
  std::vector<double> coords;
  std::unique_ptr<flann::Index<flann::L2<double>>> tree;
};

SurfelIndex::SurfelIndex(const std::vector<Eigen::Vector3d>& positions)
    : impl_(std::make_unique<Impl>()), count_(positions.size()) {
  if (positions.empty()) return;
  for (const auto& p : positions) impl_->origin += p / static_cast<double>(positions.size());
  impl_->coords.resize(3 * positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i)
    for (int a = 0; a < 3; ++a) impl_->coords[3 * i + a] = positions[i][a] - impl_->origin[a];
  flann::Matrix<double> data(impl_->coords.data(), positions.size(), 3);
  impl_->tree = std::make_unique<flann::Index<flann::L2<double>>>(
      data, flann::KDTreeSingleIndexParams(16));
  impl_->tree->buildIndex();
}

SurfelIndex::~SurfelIndex() = default;

void SurfelIndex::within(const Eigen::Vector3d& x, double radius,
                         std::vector<std::size_t>& out) const {
  out.clear();
  if (!impl_->tree || !(radius > 0.0)) return;
  double q[3];
  for (int a = 0; a < 3; ++a) q[a] = x[a] - impl_->origin[a];
  flann::Matrix<double> query(q, 1, 3);
  std::vector<std::vector<std::size_t>> ids;
  std::vector<std::vector<double>> dist2;
  flann::SearchParams params;
  params.max_neighbors = -1;
  params.sorted = false;
  impl_->tree->radiusSearch(query, ids, dist2, static_cast<float>(radius * radius), params);
  out = std::move(ids[0]);
}

void SurfelIndex::nearest(const Eigen::Vector3d& x, int k, std::vector<std::size_t>& out) const {
  out.clear();
  if (!impl_->tree || k < 1) return;
  double q[3];
  for (int a = 0; a < 3; ++a) q[a] = x[a] - impl_->origin[a];
  flann::Matrix<double> query(q, 1, 3);
  std::vector<std::vector<std::size_t>> ids;
  std::vector<std::vector<double>> dist2;
  const int n = static_cast<int>(std::min<std::size_t>(count_, static_cast<std::size_t>(k)));
  impl_->tree->knnSearch(query, ids, dist2, n, flann::SearchParams());
  out = std::move(ids[0]);
}

double mean_spacing(const std::vector<Eigen::Vector3d>& positions, const NearestPoints& nearest) {
  double sum = 0.0;
  long count = 0;
  const long n = static_cast<long>(positions.size());
#pragma omp parallel for reduction(+ : sum, count) schedule(static)
  for (long i = 0; i < n; ++i) {
    std::vector<std::size_t> near;
    nearest(static_cast<std::size_t>(i), 8, near);  // several, so that duplicates do not hide it
    for (std::size_t j : near) {
      const double d = (positions[j] - positions[i]).norm();
      if (d > 0.0) {
        sum += d;
        ++count;
        break;
      }
    }
  }
  return count > 0 ? sum / static_cast<double>(count) : 0.0;
}

double mean_spacing(const std::vector<Eigen::Vector3d>& positions, const SurfelIndex& index) {
  return mean_spacing(positions, [&](std::size_t i, int k, std::vector<std::size_t>& out) {
    index.nearest(positions[i], k, out);
  });
}

}  // namespace sss
