// Evaluates a function at many points in parallel (OpenMP), reporting progress.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "material.h"
#include "progress.h"

namespace sss {

template <typename Eval>
std::vector<Rgb> evaluate_points(const std::vector<Eigen::Vector3d>& points, const Eval& eval,
                                 const Progress& progress) {
  std::vector<Rgb> values(points.size());
  const long n = static_cast<long>(points.size());
  const long chunk = 4096;
  for (long start = 0; start < n; start += chunk) {
    const long end = std::min(n, start + chunk);
#pragma omp parallel for schedule(dynamic, 16) default(none) shared(points, values, eval, start, end)
    for (long i = start; i < end; ++i) values[i] = eval(points[i]);
    if (progress) progress(static_cast<std::size_t>(end), points.size());
  }
  return values;
}

}  // namespace sss
