#include "near_field.h"

#include <cmath>
#include <cstdint>

#include "fresnel.h"
#include "local_surface.h"

namespace sss {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kGoldenFraction = 0.6180339887498949;

// A fraction in [0, 1) per receiver, so that neighbouring receivers' nodes do not line up.
double rotation_of(std::size_t index) {
  std::uint64_t h = static_cast<std::uint64_t>(index) * 0x9E3779B97F4A7C15ull;
  h ^= h >> 29;
  h *= 0xBF58476D1CE4E5B9ull;
  h ^= h >> 32;
  return static_cast<double>(h >> 11) / 9007199254740992.0;
}

}  // namespace

NearField::NearField(const LocalSurfels& surfels, const Material& material,
                     const IlluminationSamples& light, const KernelWindow& window, double reach,
                     const NearFieldSettings& settings)
    : surfels_(surfels),
      light_(light),
      material_(material),
      dipole_(material),
      quadrature_(dipole_, window, reach, settings.quadrature),
      kappa_limit_(1.0 / quadrature_.reach()) {}

Rgb NearField::B(std::size_t receiver) const {
  Rgb sum{0.0, 0.0, 0.0};
  const Eigen::Vector3d& p = surfels_.positions[receiver];
  const bool curved = surfels_.curvature.size() == surfels_.size();
  const double kappa_given = curved ? surfels_.curvature[receiver] : 0.0;
  const double kappa_surface = std::clamp(kappa_given, -kappa_limit_, kappa_limit_);
  const double roughness = curved ? surfels_.roughness[receiver] : 0.0;
  const double thickness = surface_thickness(roughness, kappa_given, surfels_.radius);
  const double rotation = rotation_of(receiver);
  const Rgb albedo_one{1.0, 1.0, 1.0};
  for (std::size_t li = 0; li < light_.maps.size(); ++li) {
    const OrthoView& map = light_.maps[li];
    const DiscHits& hits = light_.hits[li];
    const Eigen::Vector3d& l = light_.lights[li].direction;
    const double irradiance = light_.lights[li].irradiance;
    if (irradiance == 0.0) continue;
    // The side of the receiver that faces the light (scans may hold either orientation).
    const double side = surfels_.normals[receiver].dot(l) < 0.0 ? -1.0 : 1.0;
    const Eigen::Vector3d n = side * surfels_.normals[receiver];
    const double kappa = side * kappa_surface;
    Eigen::Vector3d t1, t2;
    tangent_frame(n, t1, t2);
    const auto& rings = quadrature_.rings();
    for (std::size_t k = 0; k < rings.size(); ++k) {
      const NearFieldRing& ring = rings[k];
      const Rgb bent = NearFieldQuadrature::bend(dipole_, ring.radius, kappa);
      const double offset = rotation + kGoldenFraction * static_cast<double>(k);
      for (int a = 0; a < ring.nodes; ++a) {
        const double angle = 2.0 * kPi * (a + offset) / ring.nodes;
        const Eigen::Vector3d d = ring.radius * (std::cos(angle) * t1 + std::sin(angle) * t2);
        const SurfacePoint y = on_local_surface(p, n, kappa, d);
        const double cos_i = y.normal.dot(l);
        if (!(cos_i > 0.0)) continue;
        const double u = (y.position.dot(map.u) - map.corner.x()) / map.pixel;
        const double v = (y.position.dot(map.v) - map.corner.y()) / map.pixel;
        if (!(u >= 0.0 && v >= 0.0 && u < map.width && v < map.height)) continue;
        const std::int32_t seen =
            hits.surfel[static_cast<std::size_t>(v) * map.width + static_cast<std::size_t>(u)];
        if (seen < 0) continue;
        const SurfacePoint hit =
            seen_point(surfels_, map, hits, static_cast<int>(u), static_cast<int>(v));
        const double along = distance_to_seen_surface(y.position, l, hit.position, hit.normal);
        if (std::fabs(along) > visibility_tolerance(thickness, cos_i)) continue;
        const Rgb& albedo = surfels_.albedo.empty() ? albedo_one : surfels_.albedo[seen];
        for (int c = 0; c < 3; ++c)
          sum[c] += ring.node_weight[c] * bent[c] * irradiance *
                    fresnel_transmittance(material_.eta[c], cos_i) * cos_i * albedo[c];
      }
    }
  }
  for (double& v : sum) v /= kPi;
  return sum;
}

}  // namespace sss
