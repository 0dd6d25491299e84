#include "illumination.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "fresnel.h"
#include "local_surface.h"

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

IlluminationSamples illuminate(const LocalSurfels& surfels, const Material& material,
                               const std::vector<DirectionalLight>& lights,
                               const IlluminationSettings& settings) {
  if (!(settings.texel_per_z_r > 0.0) || settings.max_map_size < 1 ||
      settings.max_map_size > 65535) {
    std::ostringstream msg;
    msg << "[sss::illuminate] texel_per_z_r = " << settings.texel_per_z_r
        << " must be > 0 and max_map_size = " << settings.max_map_size << " in [1, 65535]";
    throw std::invalid_argument(msg.str());
  }
  if (lights.size() > 65535) throw std::invalid_argument("[sss::illuminate] too many lights");
  const Dipole dipole(material);
  const double texel = settings.texel_per_z_r * dipole.min_z_r();
  IlluminationSamples samples;
  for (std::size_t li = 0; li < lights.size(); ++li) {
    lights[li].validate();
    const Eigen::Vector3d l = lights[li].direction.normalized();
    const OrthoView map = OrthoView::fit_pixel(surfels.positions, surfels.radius, l,
                                               Eigen::Vector3d::UnitZ(), texel,
                                               settings.max_map_size);
    samples.maps.push_back(map);
    samples.lights.push_back({l, lights[li].irradiance});
    samples.hits.push_back(rasterize_discs(map, surfels.positions, surfels.normals, surfels.radius));
    if (surfels.size() == 0 || lights[li].irradiance == 0.0) continue;
    const DiscHits& hits = samples.hits.back();
    const double texel_area = map.pixel * map.pixel;
    for (int j = 0; j < map.height; ++j) {
      for (int i = 0; i < map.width; ++i) {
        const std::int32_t s = hits.surfel[static_cast<std::size_t>(j) * map.width + i];
        if (s < 0) continue;
        SurfacePoint point = seen_point(surfels, map, hits, i, j);
        if (surfels.normals[s].dot(l) < 0.0) point.normal = -point.normal;
        const Eigen::Vector3d& n = point.normal;
        const double cos_i = n.dot(l);
        if (!(cos_i > 0.0)) continue;
        Rgb power;
        for (int c = 0; c < 3; ++c) {
          power[c] = lights[li].irradiance * fresnel_transmittance(material.eta[c], cos_i) *
                     texel_area;
          if (!surfels.albedo.empty()) power[c] *= surfels.albedo[s][c];
        }
        samples.position.push_back(point.position);
        samples.normal.push_back(n);
        samples.power.push_back(power);
        samples.light.push_back(static_cast<std::uint16_t>(li));
      }
    }
  }
  return samples;
}

}  // namespace sss
