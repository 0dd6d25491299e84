#include "local_surfels.h"

#include "surface_curvature.h"

namespace sss {

LocalSurfels LocalSurfels::from(const SurfelCloud& cloud, double mm_per_unit,
                                bool with_curvature) {
  LocalSurfels local;
  local.frame.origin = cloud.empty() ? Eigen::Vector3d::Zero() : cloud.bounds().center();
  local.frame.mm_per_unit = mm_per_unit;
  local.positions.reserve(cloud.size());
  for (const auto& p : cloud.positions) {
    local.positions.push_back(local.frame.to_mm(p));
    local.bounds.extend(local.positions.back());
  }
  local.normals = cloud.normals;
  local.albedo = cloud.albedo;
  local.radius = cloud.radius * mm_per_unit;
  if (with_curvature) local.curvature = mean_curvature(local.positions, local.normals);
  return local;
}

}  // namespace sss
