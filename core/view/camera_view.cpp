#include "camera_view.h"

#include <cmath>
#include <stdexcept>

#include "disc_raster.h"
#include "fresnel.h"
#include "local_surfels.h"

namespace sss {

namespace {

// Lo = Ft(eta, |n . wo|) B at each surfel, wo(s) the unit direction towards the camera.
template <typename TowardsCamera>
std::vector<Rgb> outgoing(const SurfelCloud& cloud, const Material& material,
                          const std::vector<Rgb>& B, const TowardsCamera& wo) {
  if (B.size() != cloud.size())
    throw std::invalid_argument("[sss::outgoing_radiance] one B per surfel is needed");
  std::vector<Rgb> Lo(B.size());
  for (std::size_t s = 0; s < B.size(); ++s) {
    const double cos_o = std::fabs(cloud.normals[s].dot(wo(s)));
    for (int c = 0; c < 3; ++c) Lo[s][c] = fresnel_transmittance(material.eta[c], cos_o) * B[s][c];
  }
  return Lo;
}

}  // namespace

std::vector<Rgb> outgoing_radiance(const SurfelCloud& cloud, const Material& material,
                                   const std::vector<Rgb>& B, const Eigen::Vector3d& view_direction) {
  const Eigen::Vector3d wo = view_direction.normalized();
  return outgoing(cloud, material, B, [&wo](std::size_t) { return wo; });
}

std::vector<Rgb> outgoing_radiance_to_eye(const SurfelCloud& cloud, const Material& material,
                                          const std::vector<Rgb>& B, const Eigen::Vector3d& eye) {
  return outgoing(cloud, material, B, [&](std::size_t s) -> Eigen::Vector3d {
    return (eye - cloud.positions[s]).normalized();
  });
}

LinearImage render_view(const SurfelCloud& cloud, const Material& material,
                        const std::vector<Rgb>& B, const OrthoCamera& camera) {
  if (!camera.view_direction.allFinite() || !(camera.view_direction.norm() > 0.0))
    throw std::invalid_argument("[sss::render_view] view direction must be finite and non-zero");
  if (!camera.up.allFinite())
    throw std::invalid_argument("[sss::render_view] up vector must be finite");
  const LocalSurfels surfels = LocalSurfels::from(cloud, material.mm_per_unit);
  const OrthoView view = OrthoView::fit_image(surfels.positions, surfels.max_disc_radius(),
                                              camera.view_direction.normalized(), camera.up,
                                              camera.width, camera.height);
  const DiscHits hits = rasterize_discs(view, surfels.positions, surfels.normals,
                                        surfels.cell_radius, surfels.disc_radii);
  const std::vector<Rgb> Lo = outgoing_radiance(cloud, material, B, view.w);
  LinearImage image(camera.width, camera.height);
  for (std::size_t k = 0; k < hits.surfel.size(); ++k) {
    if (hits.surfel[k] < 0) continue;
    image.radiance[k] = Lo[hits.surfel[k]];
    image.covered[k] = 1;
  }
  return image;
}

}  // namespace sss
