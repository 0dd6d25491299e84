#include "isolated_points.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <stdexcept>

#include "surfel_index.h"

namespace sss {

void IsolationSettings::check() const {
  if (neighbours < 2 || neighbours > 256)
    throw std::invalid_argument("isolated points: neighbours must be 2 to 256, not " +
                                std::to_string(neighbours));
  if (!(ratio > 1.0))
    throw std::invalid_argument("isolated points: the ratio must be above 1, not " +
                                std::to_string(ratio));
}

std::string IsolationReport::summary() const {
  char text[128];
  std::snprintf(text, sizeof text, "%zu isolated point%s left out (largest ratio %.3g)", isolated,
                isolated == 1 ? "" : "s", largest_ratio);
  return text;
}

std::vector<bool> find_surface_points(const std::vector<Eigen::Vector3d>& positions,
                                      const IsolationSettings& settings, IsolationReport* report) {
  const std::size_t n = positions.size();
  std::vector<bool> keep(n, true);
  if (report) *report = IsolationReport{};
  if (!settings.enabled) return keep;
  settings.check();
  const int k = settings.neighbours;
  if (n <= static_cast<std::size_t>(k)) return keep;
  if (n > UINT32_MAX) throw std::invalid_argument("isolated points: over 2^32 points");

  const SurfelIndex index(positions);
  // Each point's k nearest others, k per point (32-bit indices: 64 bytes a point at k = 16).
  std::vector<std::uint32_t> neighbours(n * static_cast<std::size_t>(k));
  std::vector<double> mean_distance(n, 0.0);
#pragma omp parallel for schedule(dynamic, 256)
  for (long i = 0; i < static_cast<long>(n); ++i) {
    std::vector<std::size_t> near;
    index.nearest(positions[i], k + 1, near);  // itself among them (or a duplicate of it)
    near.erase(std::remove(near.begin(), near.end(), static_cast<std::size_t>(i)), near.end());
    near.resize(k);  // n > k: at least k others
    double sum = 0.0;
    for (int m = 0; m < k; ++m) {
      neighbours[static_cast<std::size_t>(i) * k + m] = static_cast<std::uint32_t>(near[m]);
      sum += (positions[near[m]] - positions[i]).norm();
    }
    mean_distance[i] = sum / k;
  }
  double largest = 0.0;
  std::size_t isolated = 0;
  std::vector<unsigned char> alone(n, 0);  // vector<bool> cannot be written from threads
#pragma omp parallel for schedule(static) reduction(max : largest) reduction(+ : isolated)
  for (long i = 0; i < static_cast<long>(n); ++i) {
    std::vector<double> around(k);
    for (int m = 0; m < k; ++m)
      around[m] = mean_distance[neighbours[static_cast<std::size_t>(i) * k + m]];
    std::nth_element(around.begin(), around.begin() + around.size() / 2, around.end());
    const double median = around[around.size() / 2];
    // Duplicates around a point make the median 0; a point among them is not alone.
    const double ratio = median > 0.0 ? mean_distance[i] / median : 1.0;
    largest = std::max(largest, ratio);
    if (ratio > settings.ratio) {
      alone[i] = 1;
      ++isolated;
    }
  }
  for (std::size_t i = 0; i < n; ++i) keep[i] = !alone[i];
  if (report) {
    report->tested = n;
    report->isolated = isolated;
    report->largest_ratio = largest;
  }
  return keep;
}

}  // namespace sss
