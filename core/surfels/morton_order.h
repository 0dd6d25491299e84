// Points in Morton (Z-curve) order of position, so that points near each other in space sit
// near each other in a list: the GPU's surfel list and the paper's receiver list use it.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace sss {

// 30-bit Morton code of p quantised to 1024 cells per axis over the cube at `lo` with side
// `edge` (points outside are clamped to it).
std::uint32_t morton_code(const Eigen::Vector3d& p, const Eigen::Vector3d& lo, double edge);

// The indices of `positions` sorted by Morton code over their bounding cube; ties keep input
// order.
std::vector<std::size_t> morton_order(const std::vector<Eigen::Vector3d>& positions);

}  // namespace sss
