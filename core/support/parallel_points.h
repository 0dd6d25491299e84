// Evaluates a function at many points or indices in parallel (OpenMP), reporting progress.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cstddef>
#include <vector>

#include "material.h"
#include "progress.h"

namespace sss {

// values[k] = eval(items[k]), in chunks so that progress is reported from this thread.
template <typename Item, typename Eval>
std::vector<Rgb> evaluate_each(const std::vector<Item>& items, const Eval& eval,
                               const Progress& progress) {
  std::vector<Rgb> values(items.size());
  const long n = static_cast<long>(items.size());
  const long chunk = 4096;
  for (long start = 0; start < n; start += chunk) {
    const long end = std::min(n, start + chunk);
#pragma omp parallel for schedule(dynamic, 16) default(none) shared(items, values, eval, start, end)
    for (long i = start; i < end; ++i) values[i] = eval(items[i]);
    if (progress) progress(static_cast<std::size_t>(end), items.size());
  }
  return values;
}

template <typename Eval>
std::vector<Rgb> evaluate_points(const std::vector<Eigen::Vector3d>& points, const Eval& eval,
                                 const Progress& progress) {
  return evaluate_each(points, eval, progress);
}

template <typename Eval>
std::vector<Rgb> evaluate_indices(const std::vector<std::size_t>& indices, const Eval& eval,
                                  const Progress& progress) {
  return evaluate_each(indices, eval, progress);
}

}  // namespace sss
