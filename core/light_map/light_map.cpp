#include "light_map.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace sss {

void Light::validate() const {
  if (!direction.allFinite() || !(direction.norm() > 0.0)) {
    std::ostringstream msg;
    msg << "[sss::Light] direction (" << direction.transpose()
        << ") must be finite and non-zero";
    throw std::invalid_argument(msg.str());
  }
  if (!std::isfinite(irradiance) || irradiance < 0.0) {
    std::ostringstream msg;
    msg << "[sss::Light] irradiance = " << irradiance << " must be finite and >= 0";
    throw std::invalid_argument(msg.str());
  }
  if (positional && (!position.allFinite() || !attenuation.allFinite() ||
                     attenuation.minCoeff() < 0.0 || !(attenuation.sum() > 0.0) ||
                     !std::isfinite(cone_angle) || !std::isfinite(exponent) || exponent < 0.0)) {
    std::ostringstream msg;
    msg << "[sss::Light] a positional light needs a finite position, attenuation coefficients "
           ">= 0, not all 0, and a finite cone angle and exponent >= 0 (position ("
        << position.transpose() << "), attenuation (" << attenuation.transpose()
        << "), cone " << cone_angle << ", exponent " << exponent << ")";
    throw std::invalid_argument(msg.str());
  }
}

bool Light::operator==(const Light& o) const {
  return direction == o.direction && irradiance == o.irradiance && positional == o.positional &&
         position == o.position && attenuation == o.attenuation && cone_angle == o.cone_angle &&
         exponent == o.exponent;
}

LocalLight LocalLight::of(const Light& light, const LocalFrame& frame) {
  LocalLight local;
  local.positional = light.positional;
  local.direction = light.direction.normalized();
  local.irradiance = light.irradiance;
  if (light.positional) {
    local.position = frame.to_mm(light.position);
    const double unit = frame.mm_per_unit;
    local.attenuation = {light.attenuation[0], light.attenuation[1] / unit,
                         light.attenuation[2] / (unit * unit)};
    if (light.cone_angle < 90.0) {
      local.cone_cos = std::cos(light.cone_angle * 3.14159265358979323846 / 180.0);
      local.exponent = light.exponent;
    }
  }
  return local;
}

Eigen::Vector3d LocalLight::towards(const Eigen::Vector3d& y) const {
  return positional ? (position - y).normalized() : direction;
}

double LocalLight::irradiance_at(const Eigen::Vector3d& y) const {
  if (!positional) return irradiance;
  const double d = (position - y).norm();
  double spot = 1.0;
  if (cone_cos > -1.0) {
    const double c = (position - y).dot(direction) / std::max(d, 1e-300);
    spot = c >= cone_cos ? std::pow(c, exponent) : 0.0;
  }
  return spot * irradiance / (attenuation[0] + d * (attenuation[1] + d * attenuation[2]));
}

bool LightView::texel_of(const Eigen::Vector3d& y, int& i, int& j) const {
  double a = 0.0, b = 0.0;
  if (from_point) {
    if (!perspective.project(y, a, b)) return false;
  } else {
    a = (y.dot(ortho.u) - ortho.corner.x()) / ortho.pixel;
    b = (y.dot(ortho.v) - ortho.corner.y()) / ortho.pixel;
  }
  if (!(a >= 0.0 && b >= 0.0 && a < width() && b < height())) return false;
  i = static_cast<int>(a);
  j = static_cast<int>(b);
  return true;
}

Eigen::Vector3d LightView::hit_point(const DiscHits& hits, int i, int j) const {
  if (!from_point) return hits.hit_point(ortho, i, j);
  return perspective.eye +
         hits.depth[static_cast<std::size_t>(j) * perspective.width + i] * perspective.ray(i, j);
}

LightView fit_light_view(const LocalSurfels& surfels, const LocalLight& light, double texel,
                         int max_size) {
  LightView view;
  view.from_point = light.positional;
  if (view.from_point)
    view.perspective = PerspectiveView::fit_pixel(surfels.positions, surfels.max_disc_radius(),
                                                  light.position, texel, max_size);
  else
    view.ortho = OrthoView::fit_pixel(surfels.positions, surfels.max_disc_radius(),
                                      light.direction, Eigen::Vector3d::UnitZ(), texel, max_size);
  return view;
}

LightMaps render_light_maps(const LocalSurfels& surfels, const std::vector<Light>& lights,
                            const LightMapSettings& settings) {
  if (!(settings.texel_per_radius > 0.0) || !std::isfinite(settings.texel_per_radius) ||
      settings.max_map_size < 1 || settings.max_map_size > 65535) {
    std::ostringstream msg;
    msg << "[sss::render_light_maps] texel_per_radius = " << settings.texel_per_radius
        << " must be finite and > 0 and max_map_size = " << settings.max_map_size
        << " in [1, 65535]";
    throw std::invalid_argument(msg.str());
  }
  const double texel = settings.texel_per_radius * surfels.cell_radius;
  LightMaps out;
  for (const Light& light : lights) {
    light.validate();
    const LocalLight local = LocalLight::of(light, surfels.frame);
    const LightView view = fit_light_view(surfels, local, texel, settings.max_map_size);
    out.hits.push_back(view.from_point
                           ? rasterize_discs(view.perspective, surfels.positions, surfels.normals,
                                             surfels.cell_radius, surfels.disc_radii)
                           : rasterize_discs(view.ortho, surfels.positions, surfels.normals,
                                             surfels.cell_radius, surfels.disc_radii));
    out.views.push_back(view);
    out.lights.push_back(local);
  }
  return out;
}

SurfacePoint seen_point(const LocalSurfels& surfels, const LightView& view, const DiscHits& hits,
                        int i, int j) {
  const std::int32_t s = hits.surfel[static_cast<std::size_t>(j) * view.width() + i];
  const Eigen::Vector3d hit = view.hit_point(hits, i, j);
  if (surfels.curvature.size() != surfels.size()) return {hit, surfels.normals[s]};
  const double limit = 1.0 / surfels.cell_radius;
  return on_local_surface(surfels.positions[s], surfels.normals[s],
                          std::clamp(surfels.curvature[s], -limit, limit),
                          hit - surfels.positions[s]);
}

bool light_reaches(const LocalSurfels& surfels, const LightView& view, const DiscHits& hits,
                   const Eigen::Vector3d& towards_light, const Eigen::Vector3d& y,
                   double cos_theta, double thickness) {
  int i = 0, j = 0;
  if (!view.texel_of(y, i, j)) return true;
  const std::int32_t seen_surfel = hits.surfel[static_cast<std::size_t>(j) * view.width() + i];
  if (seen_surfel < 0) return true;
  const SurfacePoint seen = seen_point(surfels, view, hits, i, j);
  const double along = distance_to_seen_surface(y, towards_light, seen.position, seen.normal);
  return std::fabs(along) <=
         visibility_tolerance(
             thickness + surfels.noise_height(static_cast<std::size_t>(seen_surfel)), cos_theta);
}

}  // namespace sss
