// The smooth surface around each surfel, fitted to its nearest neighbours (local_surface.h):
//  - mean normal curvature from how the neighbours' normals turn: on a sphere of radius R,
//    (n_j - n_i) . (p_j - p_i) = |p_j - p_i|^2 / R for every pair, so
//      kappa_i = Sum_j (n_j - n_i) . (p_j - p_i) / Sum_j |p_j - p_i|^2
//    is 1 / R there, positive where the surface bends away from n_i (outward normals of a
//    convex object), and an average of the principal curvatures elsewhere;
//  - roughness: the RMS height of the neighbours off the osculating paraboloid
//      sigma_i = RMS_j ((p_j - p_i) . n_i + kappa_i |d_j|^2 / 2),  d_j the tangential offset,
//    0 on a smooth sampled surface; on a scan with depth noise s it is about sqrt(2) s, the
//    noise of a height difference.
// Neighbours facing away from n_i and well off its tangent plane lie on the other side of a
// thin part and are left out (else both sheets would count as one rough surface); the rest
// have their normals turned to agree with n_i, so a flipped normal on the same sheet does not
// matter.
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
