#include "procedural_shapes.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace sss {
namespace {
constexpr double kPi = 3.14159265358979323846;

void check(double length, const char* name) {
  if (!std::isfinite(length) || length <= 0.0)
    throw std::invalid_argument(std::string("[sss::procedural_shapes] ") + name +
                                " must be finite and > 0");
}

void finish(SurfelCloud& cloud, double spacing) {
  // Even rings leave gaps of up to about one spacing between neighbours along the diagonal.
  cloud.radius = 0.8 * spacing;
  cloud.validate();
}
}  // namespace

SurfelCloud make_slab(double disc_radius, double spacing) {
  check(disc_radius, "disc radius");
  check(spacing, "spacing");
  SurfelCloud cloud;
  const int n = static_cast<int>(std::floor(disc_radius / spacing));
  for (int j = -n; j <= n; ++j)
    for (int i = -n; i <= n; ++i)
      if ((i * i + j * j) * spacing * spacing <= disc_radius * disc_radius) {
        cloud.positions.emplace_back(i * spacing, j * spacing, 0.0);
        cloud.normals.emplace_back(0.0, 0.0, 1.0);
      }
  cloud.radius = 0.75 * spacing;
  cloud.validate();
  return cloud;
}

SurfelCloud make_random_slab(double disc_radius, double spacing, unsigned seed) {
  check(disc_radius, "disc radius");
  check(spacing, "spacing");
  // A Poisson process of density lambda has mean nearest-neighbour distance 1 / (2 sqrt(lambda)).
  const double density = 0.25 / (spacing * spacing);
  const auto count = static_cast<std::size_t>(std::llround(density * kPi * disc_radius * disc_radius));
  SurfelCloud cloud;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> along(-disc_radius, disc_radius);
  while (cloud.size() < count) {
    const Eigen::Vector3d p(along(rng), along(rng), 0.0);
    if (p.squaredNorm() > disc_radius * disc_radius) continue;
    cloud.positions.push_back(p);
    cloud.normals.emplace_back(0.0, 0.0, 1.0);
  }
  cloud.radius = 1.5 * spacing;
  cloud.validate();
  return cloud;
}

SurfelCloud make_torus(double R, double r, double spacing) {
  check(R, "ring radius");
  check(r, "tube radius");
  check(spacing, "spacing");
  SurfelCloud cloud;
  const int rings = std::max(3, static_cast<int>(std::round(2 * kPi * r / spacing)));
  for (int a = 0; a < rings; ++a) {
    const double v = 2 * kPi * (a + 0.5) / rings;
    const double ring = R + r * std::cos(v);
    const int count = std::max(3, static_cast<int>(std::round(2 * kPi * ring / spacing)));
    for (int b = 0; b < count; ++b) {
      const double u = 2 * kPi * (b + 0.5 * (a % 2)) / count;
      const Eigen::Vector3d n(std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v));
      cloud.positions.emplace_back(ring * std::cos(u), ring * std::sin(u), r * std::sin(v));
      cloud.normals.push_back(n);
    }
  }
  finish(cloud, spacing);
  return cloud;
}

SurfelCloud make_line(int count, double spacing) {
  check(spacing, "spacing");
  SurfelCloud cloud;
  for (int i = 0; i < count; ++i) {
    cloud.positions.emplace_back(i * spacing, 0.0, 0.0);
    cloud.normals.emplace_back(0.0, 0.0, 1.0);
  }
  cloud.radius = spacing;
  cloud.validate();
  return cloud;
}

SurfelCloud make_sphere(double r, double spacing) {
  check(r, "radius");
  check(spacing, "spacing");
  SurfelCloud cloud;
  const int rings = std::max(2, static_cast<int>(std::round(kPi * r / spacing)));
  for (int a = 0; a < rings; ++a) {
    const double theta = kPi * (a + 0.5) / rings;
    const int count = std::max(3, static_cast<int>(std::round(2 * kPi * r * std::sin(theta) / spacing)));
    for (int b = 0; b < count; ++b) {
      const double phi = 2 * kPi * (b + 0.5 * (a % 2)) / count;
      const Eigen::Vector3d n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                              std::cos(theta));
      cloud.positions.push_back(r * n);
      cloud.normals.push_back(n);
    }
  }
  finish(cloud, spacing);
  return cloud;
}

SurfelCloud make_fibonacci_sphere(double r, int count) {
  check(r, "radius");
  if (count < 2) throw std::invalid_argument("[sss::procedural_shapes] count must be >= 2");
  SurfelCloud cloud;
  const double golden_angle = kPi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / count;
    const double ring = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = golden_angle * i;
    const Eigen::Vector3d n(ring * std::cos(phi), ring * std::sin(phi), z);
    cloud.positions.push_back(r * n);
    cloud.normals.push_back(n);
  }
  cloud.radius = r;  // any positive value passes validation; the spacing follows
  cloud.validate();
  cloud.radius = 1.5 * cloud.mean_spacing();
  return cloud;
}

}  // namespace sss
