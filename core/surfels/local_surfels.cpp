#include "local_surfels.h"

#include "local_surface.h"
#include "surface_fit.h"

#include <algorithm>
#include <utility>

namespace sss {

LocalSurfels LocalSurfels::from(const SurfelCloud& cloud, double mm_per_unit,
                                bool with_surface_fit) {
  LocalSurfels local;
  local.frame.origin = cloud.empty() ? Eigen::Vector3d::Zero() : cloud.bounds().frame_origin();
  local.frame.mm_per_unit = mm_per_unit;
  local.positions.reserve(cloud.size());
  for (const auto& p : cloud.positions) {
    local.positions.push_back(local.frame.to_mm(p));
    local.bounds.extend(local.positions.back());
  }
  local.normals = cloud.normals;
  local.albedo = cloud.albedo;
  local.cell_radius = cloud.radius * mm_per_unit;
  local.disc_radii.reserve(cloud.radii.size());
  for (double r : cloud.radii) local.disc_radii.push_back(std::max(r, cloud.radius) * mm_per_unit);
  if (with_surface_fit) {
    SurfaceFit fit = fit_local_surfaces(local.positions, local.normals);
    local.curvature = std::move(fit.curvature);
    local.roughness = std::move(fit.roughness);
  }
  return local;
}

double LocalSurfels::thickness(std::size_t i) const {
  const bool fitted = roughness.size() == positions.size();
  return surface_thickness(fitted ? roughness[i] : 0.0, fitted ? curvature[i] : 0.0, cell_radius);
}

double LocalSurfels::noise_height(std::size_t i) const {
  return roughness.size() == positions.size() ? sss::noise_height(roughness[i]) : 0.0;
}

double LocalSurfels::max_disc_radius() const {
  double r = cell_radius;
  for (double d : disc_radii) r = std::max(r, d);
  return r;
}

}  // namespace sss
