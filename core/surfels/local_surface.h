// The smooth local surface that the near field integrates over and that lifts the light's
// samples off the flat discs: around a surfel at p with unit normal n and mean curvature kappa
// (1 / radius, > 0 where the surface bends away from n), the osculating paraboloid
//   x(d) = p + d - kappa |d|^2 / 2 n,   n(d) = normalize(n + kappa d),
// for an offset d in the tangent plane. Flat discs overlap above a curved surface by up to
// kappa r^2 / 2 and scanner noise stacks them further; taking the near field on this surface
// instead makes it independent of how the surface was sampled. The GPU evaluates the same
// surface where it samples a cell's light (surfel_irradiance_fs.glsl).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace sss {

struct SurfacePoint {
  Eigen::Vector3d position;
  Eigen::Vector3d normal;
};

inline SurfacePoint on_local_surface(const Eigen::Vector3d& p, const Eigen::Vector3d& n,
                                     double kappa, const Eigen::Vector3d& d) {
  return {p + d - 0.5 * kappa * d.squaredNorm() * n, (n + kappa * d).normalized()};
}

// A tangent frame of n, the same for n and -n (so that a flipped normal lays out the same
// points): t1 from the normal turned to have its largest component positive, t2 = n x t1.
inline void tangent_frame(const Eigen::Vector3d& n, Eigen::Vector3d& t1, Eigen::Vector3d& t2) {
  int axis;
  n.cwiseAbs().maxCoeff(&axis);
  const Eigen::Vector3d m = n[axis] < 0.0 ? Eigen::Vector3d(-n) : n;
  const Eigen::Vector3d helper =
      std::fabs(m.x()) < 0.7 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  t1 = m.cross(helper).normalized();
  t2 = m.cross(t1);
}

// How far along the light, from a node y towards the light, the local surface of the disc the
// light sees at y's texel lies: that disc's point and normal at the texel centre (on its local
// surface) give a plane, met at this distance by the ray from y towards the light. Measured
// against the plane rather than the texel's own depth, it carries no error from where in the
// texel y falls.
inline double distance_to_seen_surface(const Eigen::Vector3d& y, const Eigen::Vector3d& towards,
                                       const Eigen::Vector3d& seen_point,
                                       const Eigen::Vector3d& seen_normal) {
  return (seen_point - y).dot(seen_normal) / std::max(std::fabs(seen_normal.dot(towards)), 0.05);
}

// How far scanner noise may leave a surfel off the surface it measured (mm, along the normal):
// three times its roughness.
inline double noise_height(double roughness) { return 3.0 * roughness; }

// How far off a surfel's local surface (mm, along the normal) the discs the light sees there
// may stand and still be that surface: its noise height, the height kappa r^2 by which flat
// discs of radius r stack above a curved surface, and a twentieth of a disc radius. An occluder
// must stand farther off to shadow the surface.
inline double surface_thickness(double roughness, double kappa, double disc_radius) {
  return noise_height(roughness) + std::fabs(kappa) * disc_radius * disc_radius +
         0.05 * disc_radius;
}

// A node belongs to the surface the light sees when that surface is within this distance of
// it along the light: `thickness` is along the normal (the node's surfel's thickness and the
// seen disc's noise height together), cos_theta the node's cosine to the light (a height along
// the normal is height / cos_theta along the light).
inline double visibility_tolerance(double thickness, double cos_theta) {
  return thickness / std::max(cos_theta, 0.1);
}

}  // namespace sss
