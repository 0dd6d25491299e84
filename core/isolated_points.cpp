#include "isolated_points.h"

#include <algorithm>
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

std::string IsolationSettings::summary() const {
  if (!enabled) return "isolated points kept";
  char text[96];
  std::snprintf(text, sizeof text, "isolated points left out (%d neighbours, ratio %g)",
                neighbours, ratio);
  return text;
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

  const SurfelIndex index(positions);
  std::vector<std::vector<std::size_t>> neighbours(n);
  std::vector<double> mean_distance(n, 0.0);
#pragma omp parallel for schedule(dynamic, 256)
  for (long i = 0; i < static_cast<long>(n); ++i) {
    std::vector<std::size_t>& near = neighbours[i];
    index.nearest(positions[i], k + 1, near);  // itself among them (or a duplicate of it)
    near.erase(std::remove(near.begin(), near.end(), static_cast<std::size_t>(i)), near.end());
    near.resize(std::min<std::size_t>(near.size(), k));
    double sum = 0.0;
    for (std::size_t j : near) sum += (positions[j] - positions[i]).norm();
    mean_distance[i] = near.empty() ? 0.0 : sum / static_cast<double>(near.size());
  }
  double largest = 0.0;
  std::size_t isolated = 0;
  std::vector<unsigned char> alone(n, 0);  // vector<bool> cannot be written from threads
#pragma omp parallel for schedule(static) reduction(max : largest) reduction(+ : isolated)
  for (long i = 0; i < static_cast<long>(n); ++i) {
    std::vector<double> around;
    around.reserve(neighbours[i].size());
    for (std::size_t j : neighbours[i]) around.push_back(mean_distance[j]);
    if (around.empty()) continue;
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
