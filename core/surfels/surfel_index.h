// A k-d tree over surfel positions (FLANN), for the neighbourhoods of step 2.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

namespace sss {

class SurfelIndex {
 public:
  explicit SurfelIndex(const std::vector<Eigen::Vector3d>& positions);
  ~SurfelIndex();
  SurfelIndex(const SurfelIndex&) = delete;
  SurfelIndex& operator=(const SurfelIndex&) = delete;

  // Indices of the points within `radius` of x (unsorted). Thread-safe.
  void within(const Eigen::Vector3d& x, double radius, std::vector<std::size_t>& out) const;
  // Indices of the k nearest points to x, nearest first (fewer when there are fewer points).
  void nearest(const Eigen::Vector3d& x, int k, std::vector<std::size_t>& out) const;
  std::size_t size() const { return count_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::size_t count_ = 0;
};

// Point i's k nearest points (itself among them), nearest first; called from several threads.
using NearestPoints = std::function<void(std::size_t i, int k, std::vector<std::size_t>& out)>;

// Mean distance from a point to its nearest other point (duplicates skipped; 0 when every
// point sits at one place), with the neighbours of any index over `positions` (the PCL glue
// passes PCL's kd-tree).
double mean_spacing(const std::vector<Eigen::Vector3d>& positions, const NearestPoints& nearest);
// The same with `index` built over `positions`.
double mean_spacing(const std::vector<Eigen::Vector3d>& positions, const SurfelIndex& index);

}  // namespace sss
