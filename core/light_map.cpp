#include "light_map.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace sss {

void DirectionalLight::validate() const {
  if (!direction.allFinite() || !(direction.norm() > 0.0)) {
    std::ostringstream msg;
    msg << "[sss::DirectionalLight] direction (" << direction.transpose()
        << ") must be finite and non-zero";
    throw std::invalid_argument(msg.str());
  }
  if (!std::isfinite(irradiance) || irradiance < 0.0) {
    std::ostringstream msg;
    msg << "[sss::DirectionalLight] irradiance = " << irradiance << " must be finite and >= 0";
    throw std::invalid_argument(msg.str());
  }
}

LightMaps render_light_maps(const LocalSurfels& surfels, const std::vector<DirectionalLight>& lights,
                            const LightMapSettings& settings) {
  if (!(settings.texel_per_radius > 0.0) || !std::isfinite(settings.texel_per_radius) ||
      settings.max_map_size < 1 || settings.max_map_size > 65535) {
    std::ostringstream msg;
    msg << "[sss::render_light_maps] texel_per_radius = " << settings.texel_per_radius
        << " must be finite and > 0 and max_map_size = " << settings.max_map_size
        << " in [1, 65535]";
    throw std::invalid_argument(msg.str());
  }
  const double texel = settings.texel_per_radius * surfels.radius;
  LightMaps out;
  for (const DirectionalLight& light : lights) {
    light.validate();
    const Eigen::Vector3d l = light.direction.normalized();
    const OrthoView map = OrthoView::fit_pixel(surfels.positions, surfels.max_disc_radius(), l,
                                               Eigen::Vector3d::UnitZ(), texel,
                                               settings.max_map_size);
    out.maps.push_back(map);
    out.lights.push_back({l, light.irradiance});
    out.hits.push_back(rasterize_discs(map, surfels.positions, surfels.normals, surfels.radius,
                                       surfels.disc_radii));
  }
  return out;
}

SurfacePoint seen_point(const LocalSurfels& surfels, const OrthoView& map, const DiscHits& hits,
                        int i, int j) {
  const std::int32_t s = hits.surfel[static_cast<std::size_t>(j) * map.width + i];
  const Eigen::Vector3d hit = hits.hit_point(map, i, j);
  if (surfels.curvature.size() != surfels.size()) return {hit, surfels.normals[s]};
  const double limit = 1.0 / surfels.radius;
  return on_local_surface(surfels.positions[s], surfels.normals[s],
                          std::clamp(surfels.curvature[s], -limit, limit),
                          hit - surfels.positions[s]);
}

bool light_reaches(const LocalSurfels& surfels, const OrthoView& map, const DiscHits& hits,
                   const Eigen::Vector3d& towards_light, const Eigen::Vector3d& y,
                   double cos_theta, double thickness) {
  const double u = (y.dot(map.u) - map.corner.x()) / map.pixel;
  const double v = (y.dot(map.v) - map.corner.y()) / map.pixel;
  if (!(u >= 0.0 && v >= 0.0 && u < map.width && v < map.height)) return true;
  const int i = static_cast<int>(u), j = static_cast<int>(v);
  if (hits.surfel[static_cast<std::size_t>(j) * map.width + i] < 0) return true;
  const SurfacePoint seen = seen_point(surfels, map, hits, i, j);
  const double along = distance_to_seen_surface(y, towards_light, seen.position, seen.normal);
  return std::fabs(along) <= visibility_tolerance(thickness, cos_theta);
}

}  // namespace sss
