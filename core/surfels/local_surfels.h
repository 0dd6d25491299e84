// Surfels in the renderer's local millimetre frame (see LocalFrame).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "surfel_cloud.h"

namespace sss {

struct LocalSurfels {
  LocalFrame frame;
  std::vector<Eigen::Vector3d> positions;  // mm, relative to frame.origin
  std::vector<Eigen::Vector3d> normals;    // unit
  std::vector<Rgb> albedo;                 // empty or one per surfel
  std::vector<double> curvature;           // 1/mm (surface_fit.h); empty: flat discs
  std::vector<double> roughness;           // mm (surface_fit.h); empty with the curvature
  double cell_radius = 0.0;                // mm: the cells' (dA's) radius and the texel's scale
  std::vector<double> disc_radii;          // mm: each disc as the light sees it (empty: radius):
                                           // the radius that closes the surface (splat_coverage.h),
                                           // at least `radius` (smaller flat discs open gaps where
                                           // the surface turns away from the light)
  Bounds bounds;                           // of positions, mm

  // The cloud must have been validated (SurfelCloud::validate). The local surface fit costs a
  // nearest-neighbour search; views that only show given radiance can do without it.
  static LocalSurfels from(const SurfelCloud& cloud, double mm_per_unit,
                           bool with_surface_fit = true);
  std::size_t size() const { return positions.size(); }
  double disc_radius(std::size_t i) const {
    return disc_radii.empty() ? cell_radius : disc_radii[i];
  }
  double max_disc_radius() const;
  // How far off its local surface surfel i's discs may stand and still be it (local_surface.h
  // surface_thickness, with roughness and curvature 0 without the surface fit), mm.
  double thickness(std::size_t i) const;
  // How far its noise may leave surfel i off the surface it measured (local_surface.h
  // noise_height; 0 without the surface fit), mm.
  double noise_height(std::size_t i) const;
};

}  // namespace sss
