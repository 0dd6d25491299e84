#include "surfel_irradiance.h"

#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "fresnel.h"

namespace sss {
namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kGoldenAngle = 2.399963229728653;
}  // namespace

double pattern_rotation(std::size_t index) {
  std::uint64_t h = static_cast<std::uint64_t>(index) * 0x9E3779B97F4A7C15ull;
  h ^= h >> 29;
  h *= 0xBF58476D1CE4E5B9ull;
  h ^= h >> 32;
  return static_cast<double>(h >> 11) / 9007199254740992.0;
}

SurfelIrradiance surfel_irradiance(const LocalSurfels& surfels, const std::vector<double>& area,
                                   const Material& material, const LightMaps& light,
                                   int samples, int refined) {
  if (area.size() != surfels.size() || samples < 1 || refined < samples)
    throw std::invalid_argument(
        "[sss::surfel_irradiance] one cell area per surfel, at least one sample and at least as "
        "many refined ones are needed");
  const std::size_t n = surfels.size();
  const double limit = 1.0 / surfels.cell_radius;
  SurfelIrradiance E(light.size(), std::vector<Rgb>(n, Rgb{0.0, 0.0, 0.0}));
  for (std::size_t li = 0; li < light.size(); ++li) {
    const LocalLight& source = light.lights[li];
    if (source.irradiance == 0.0) continue;
    const long count = static_cast<long>(n);
    std::vector<Rgb>& out = E[li];
#pragma omp parallel for schedule(dynamic, 256) default(none) \
    shared(surfels, area, material, light, out, source, count, samples, refined, limit, li)
    for (long j = 0; j < count; ++j) {
      const double side = surfels.normals[j].dot(source.towards(surfels.positions[j])) < 0.0 ? -1.0 : 1.0;
      const Eigen::Vector3d n = side * surfels.normals[j];
      const double kappa = side * std::clamp(surfels.curvature[j], -limit, limit);
      const double thickness = surfels.thickness(j);
      const double cell_radius = std::sqrt(area[j] / kPi);
      Eigen::Vector3d t1, t2;
      tangent_frame(n, t1, t2);
      const double turn = 2.0 * kPi * pattern_rotation(static_cast<std::size_t>(j));
      // Ft cos V summed over `count` points; `lit` counts the points with light.
      const auto sample = [&](int count, int& lit) {
        Rgb sum{0.0, 0.0, 0.0};
        lit = 0;
        for (int s = 0; s < count; ++s) {
          const double rho = cell_radius * std::sqrt((s + 0.5) / count);
          const double angle = turn + kGoldenAngle * s;
          const SurfacePoint y = on_local_surface(
              surfels.positions[j], n, kappa, rho * (std::cos(angle) * t1 + std::sin(angle) * t2));
          const Eigen::Vector3d l = source.towards(y.position);
          const double cos_i = y.normal.dot(l);
          if (!(cos_i > 0.0)) continue;
          if (!light_reaches(surfels, light.views[li], light.hits[li], l, y.position, cos_i,
                             thickness))
            continue;
          ++lit;
          const double e = source.irradiance_at(y.position);
          for (int c = 0; c < 3; ++c)
            sum[c] += e * fresnel_transmittance(material.eta[c], cos_i) * cos_i / count;
        }
        return sum;
      };
      int lit = 0;
      Rgb sum = sample(samples, lit);
      if (lit > 0 && lit < samples && refined > samples) sum = sample(refined, lit);
      for (int c = 0; c < 3; ++c) {
        const double albedo = surfels.albedo.empty() ? 1.0 : surfels.albedo[j][c];
        out[j][c] = albedo * sum[c];
      }
    }
  }
  return E;
}

std::vector<Rgb> total_irradiance(const SurfelIrradiance& E, std::size_t surfels) {
  std::vector<Rgb> total(surfels, Rgb{0.0, 0.0, 0.0});
  for (const auto& per_light : E)
    for (std::size_t j = 0; j < per_light.size(); ++j)
      for (int c = 0; c < 3; ++c) total[j][c] += per_light[j][c];
  return total;
}

}  // namespace sss
