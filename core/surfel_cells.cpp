#include "surfel_cells.h"

#include <cmath>
#include <limits>

#include "local_surface.h"
#include "surfel_irradiance.h"

namespace sss {
namespace {
constexpr int kCellSamples = 64;
constexpr double kGoldenAngle = 2.399963229728653;
}  // namespace

bool on_same_surface(const LocalSurfels& surfels, std::size_t i, std::size_t j, double thickness) {
  const Eigen::Vector3d& n = surfels.normals[i];
  if (std::fabs(n.dot(surfels.normals[j])) < 0.5) return false;
  const Eigen::Vector3d d = surfels.positions[j] - surfels.positions[i];
  const double along = d.dot(n);
  const double height = along + 0.5 * surfels.curvature[i] * (d.squaredNorm() - along * along);
  return std::fabs(height) <= thickness;
}

std::vector<double> cell_areas(const LocalSurfels& surfels, const SurfelIndex& index) {
  const std::size_t n = surfels.size();
  std::vector<double> area(n, 0.0);
  const double r = surfels.radius;
  const double disc_area = 3.14159265358979323846 * r * r;
  const long count = static_cast<long>(n);
#pragma omp parallel default(none) shared(surfels, index, area, count, r, disc_area)
  {
    std::vector<std::size_t> near, same;
#pragma omp for schedule(dynamic, 256)
    for (long i = 0; i < count; ++i) {
      const Eigen::Vector3d& p = surfels.positions[i];
      const Eigen::Vector3d& normal = surfels.normals[i];
      const double kappa = std::clamp(surfels.curvature[i], -1.0 / r, 1.0 / r);
      const double thickness = surface_thickness(surfels.roughness[i], surfels.curvature[i], r);
      index.within(p, 2.0 * r, near);
      same.clear();
      for (std::size_t j : near)
        if (j != static_cast<std::size_t>(i) && on_same_surface(surfels, i, j, thickness))
          same.push_back(j);
      Eigen::Vector3d t1, t2;
      tangent_frame(normal, t1, t2);
      // Turned per surfel, so that the samples' count of a regular lattice's identical cells
      // errs in both directions instead of the same one everywhere.
      const double turn = 6.283185307179586 * pattern_rotation(static_cast<std::size_t>(i));
      int owned = 0;
      for (int q = 0; q < kCellSamples; ++q) {
        const double rho = r * std::sqrt((q + 0.5) / kCellSamples);
        const double angle = turn + kGoldenAngle * q;
        const SurfacePoint y = on_local_surface(
            p, normal, kappa, rho * (std::cos(angle) * t1 + std::sin(angle) * t2));
        const double own = (y.position - p).squaredNorm();
        bool mine = true;
        for (std::size_t j : same) {  // ties (duplicate points) go to the lower index
          const double other = (y.position - surfels.positions[j]).squaredNorm();
          if (other < own || (other == own && j < static_cast<std::size_t>(i))) {
            mine = false;
            break;
          }
        }
        if (mine) ++owned;
      }
      area[i] = disc_area * owned / kCellSamples;
    }
  }
  return area;
}

}  // namespace sss
