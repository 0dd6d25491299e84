// Mean normal curvature of the surface at each surfel, from how its neighbours' normals turn:
// on a sphere of radius R, (n_j - n_i) . (p_j - p_i) = |p_j - p_i|^2 / R for every pair, so
//   kappa_i = Sum_j (n_j - n_i) . (p_j - p_i) / Sum_j |p_j - p_i|^2
// over the nearest neighbours (normals turned to agree with n_i first) is 1 / R there, positive
// where the surface bends away from n_i (outward normals of a convex object), and an average of
// the principal curvatures elsewhere. Feeds local_surface.h.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace sss {

// positions and unit normals in one unit; the result is in 1 / that unit, 0 for points without
// distinct neighbours. `neighbours` >= 1.
std::vector<double> mean_curvature(const std::vector<Eigen::Vector3d>& positions,
                                   const std::vector<Eigen::Vector3d>& normals,
                                   int neighbours = 16);

}  // namespace sss
