// The smooth surface around each surfel, fitted to its nearest neighbours (local_surface.h):
//  - mean normal curvature from how the neighbours' normals turn: on a sphere of radius R,
//    (n_j - n_i) . (p_j - p_i) = |p_j - p_i|^2 / R for every pair, so
//      kappa_i = Sum_j (n_j - n_i) . (p_j - p_i) / Sum_j |p_j - p_i|^2
//    is 1 / R there, positive where the surface bends away from n_i (outward normals of a
//    convex object), and an average of the principal curvatures elsewhere;
//  - roughness: the RMS height of the neighbours off the osculating paraboloid
//      sigma_i = RMS_j ((p_j - p_i) . n_i + kappa_i |d_j|^2 / 2),  d_j the tangential offset,
//    0 on a smooth sampled surface, the depth noise on a scan.
// Normals are turned to agree with n_i first, so orientation does not matter.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace sss {

struct SurfaceFit {
  std::vector<double> curvature;  // 1 / unit of the positions
  std::vector<double> roughness;  // unit of the positions
};

// 0 for points without distinct neighbours. `neighbours` >= 1. Throws std::invalid_argument
// for sizes that differ.
SurfaceFit fit_local_surfaces(const std::vector<Eigen::Vector3d>& positions,
                              const std::vector<Eigen::Vector3d>& normals, int neighbours = 16);

}  // namespace sss
