#include "morton_order.h"

#include <algorithm>
#include <numeric>

namespace sss {

std::uint32_t morton_code(const Eigen::Vector3d& p, const Eigen::Vector3d& lo, double edge) {
  std::uint32_t code = 0;
  for (int a = 0; a < 3; ++a) {
    const double t = edge > 0.0 ? (p[a] - lo[a]) / edge : 0.0;
    const auto q = static_cast<std::uint32_t>(std::clamp(t * 1024.0, 0.0, 1023.0));
    for (int b = 0; b < 10; ++b) {
      code |= ((q >> b) & 1u) << (3 * b + a);
    }
  }
  return code;
}

std::vector<std::size_t> morton_order(const std::vector<Eigen::Vector3d>& positions) {
  const std::size_t n = positions.size();
  Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();
  if (n > 0) {
    lo = hi = positions[0];
  }
  for (const Eigen::Vector3d& p : positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double edge = (hi - lo).maxCoeff();
  std::vector<std::uint32_t> code(n);
  for (std::size_t i = 0; i < n; ++i) {
    code[i] = morton_code(positions[i], lo, edge);
  }
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return code[a] < code[b]; });
  return order;
}

}  // namespace sss
