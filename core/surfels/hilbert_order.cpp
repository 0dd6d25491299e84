#include "hilbert_order.h"

#include <algorithm>
#include <numeric>

namespace sss {
namespace {
constexpr int kBits = 21;  // per axis: 63 bits in all
}

// Skilling's construction (AIP Conf. Proc. 707, 2004): the cell's coordinates are turned, bit
// plane by bit plane from the top, into the "transposed" Hilbert index, whose bits interleaved
// give the index.
std::uint64_t hilbert_index(const Eigen::Vector3d& p, const Eigen::Vector3d& lo, double edge) {
  constexpr double cells = static_cast<double>(1u << kBits);
  std::uint32_t X[3];
  for (int a = 0; a < 3; ++a) {
    const double t = edge > 0.0 ? (p[a] - lo[a]) / edge : 0.0;
    X[a] = static_cast<std::uint32_t>(std::clamp(t * cells, 0.0, cells - 1.0));
  }
  const std::uint32_t top = 1u << (kBits - 1);
  for (std::uint32_t q = top; q > 1; q >>= 1) {
    const std::uint32_t below = q - 1;
    for (int i = 0; i < 3; ++i) {
      if (X[i] & q) {
        X[0] ^= below;  // reflect
      } else {
        const std::uint32_t swap = (X[0] ^ X[i]) & below;  // exchange the low bits
        X[0] ^= swap;
        X[i] ^= swap;
      }
    }
  }
  for (int i = 1; i < 3; ++i) X[i] ^= X[i - 1];  // Gray code
  std::uint32_t flip = 0;
  for (std::uint32_t q = top; q > 1; q >>= 1) {
    if (X[2] & q) flip ^= q - 1;
  }
  for (std::uint32_t& x : X) x ^= flip;
  std::uint64_t index = 0;
  for (int b = kBits - 1; b >= 0; --b) {
    for (int i = 0; i < 3; ++i) index = (index << 1) | ((X[i] >> b) & 1u);
  }
  return index;
}

std::vector<std::size_t> hilbert_order(const std::vector<Eigen::Vector3d>& positions) {
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
  std::vector<std::uint64_t> index(n);
  for (std::size_t i = 0; i < n; ++i) {
    index[i] = hilbert_index(positions[i], lo, edge);
  }
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return index[a] < index[b]; });
  return order;
}

}  // namespace sss
