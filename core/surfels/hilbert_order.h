// Points in the order of a 3-D Hilbert curve through their bounding cube, so that points near
// each other in space sit near each other in a list: the GPU's surfel list (whose 2 x 2 texel
// squares are the far field's source groups) and the paper's receiver list use it. Unlike a
// Z-curve, a Hilbert curve only steps between neighbouring cells, so that a run of consecutive
// points is a compact group more often: on the Kinect table scene, 25 % fewer groups in the far
// field's walk.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace sss {

// Position along the Hilbert curve of 2^21 cells per axis over the cube at `lo` with side
// `edge` (points outside are clamped to it), a 63-bit number.
std::uint64_t hilbert_index(const Eigen::Vector3d& p, const Eigen::Vector3d& lo, double edge);

// The indices of `positions` sorted by Hilbert index over their bounding cube; ties keep input
// order.
std::vector<std::size_t> hilbert_order(const std::vector<Eigen::Vector3d>& positions);

}  // namespace sss
