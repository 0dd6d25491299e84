#include "near_field.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "local_surface.h"
#include "surfel_cells.h"
#include "surfel_irradiance.h"

namespace sss {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kGoldenFraction = 0.6180339887498949;

struct Row {
  std::vector<std::uint32_t> source;
  std::vector<Rgb> weight;
  void add(std::uint32_t j, const Rgb& w) {
    for (std::size_t k = 0; k < source.size(); ++k)
      if (source[k] == j) {
        for (int c = 0; c < 3; ++c) weight[k][c] += w[c];
        return;
      }
    source.push_back(j);
    weight.push_back(w);
  }
};

}  // namespace

Rgb NearFieldWeights::B(std::size_t row, const std::vector<Rgb>& E) const {
  Rgb sum{0.0, 0.0, 0.0};
  for (std::uint32_t e = first[row]; e < first[row + 1]; ++e)
    for (int c = 0; c < 3; ++c) sum[c] += weight[e][c] * E[source[e]][c];
  for (double& v : sum) v /= kPi;
  return sum;
}

// Eq. 3 over a cell of area `area` around p (normal n) at the receiver x, with the fraction
// `keep(r)` of it kept, summed over points spread evenly over a disc of that area.
template <typename Keep>
Rgb cell_kernel(const Dipole& dipole, const Eigen::Vector3d& p, const Eigen::Vector3d& n,
                double area, const Eigen::Vector3d& x, const Keep& keep) {
  constexpr int kPoints = 32;
  constexpr double kGoldenAngle = 2.399963229728653;
  Eigen::Vector3d t1, t2;
  tangent_frame(n, t1, t2);
  const double radius = std::sqrt(area / kPi);
  Rgb sum{0.0, 0.0, 0.0};
  for (int s = 0; s < kPoints; ++s) {
    const double rho = radius * std::sqrt((s + 0.5) / kPoints);
    const double angle = kGoldenAngle * s;
    const Eigen::Vector3d q = p + rho * (std::cos(angle) * t1 + std::sin(angle) * t2);
    const double k = keep((q - x).norm());
    if (k <= 0.0) continue;
    for (int c = 0; c < 3; ++c) {
      const DipoleChannel& ch = dipole.channel[c];
      sum[c] += k * ch.Rd_from_distances((q - ch.z_r * n - x).norm(), (q + ch.z_v * n - x).norm());
    }
  }
  for (double& v : sum) v *= area / kPoints;
  return sum;
}

NearFieldWeights near_field_weights(const LocalSurfels& surfels, const std::vector<double>& area,
                                    const SurfelIndex& index, const Dipole& dipole,
                                    const NearFieldQuadrature& quadrature,
                                    const KernelWindow& window,
                                    const std::vector<std::size_t>& receivers, bool whole_cells) {
  const std::size_t n = receivers.empty() ? surfels.size() : receivers.size();
  std::vector<Row> rows(n);
  const double r = surfels.radius;
  const double reach = quadrature.reach();
  const double kappa_limit = 1.0 / reach;
  const long count = static_cast<long>(n);
#pragma omp parallel default(none) shared(surfels, area, index, dipole, quadrature, window, \
                                          receivers, rows, count, r, reach, kappa_limit, whole_cells)
  {
    std::vector<std::size_t> near, other;
    std::vector<std::pair<double, std::size_t>> same;  // distance from the receiver, index
#pragma omp for schedule(dynamic, 64)
    for (long k = 0; k < count; ++k) {
      const std::size_t o = receivers.empty() ? static_cast<std::size_t>(k) : receivers[k];
      const Eigen::Vector3d& p = surfels.positions[o];
      const Eigen::Vector3d& normal = surfels.normals[o];
      const double kappa = std::clamp(surfels.curvature[o], -kappa_limit, kappa_limit);
      const double thickness = surface_thickness(surfels.roughness[o], surfels.curvature[o], r);
      index.within(p, reach + r, near);
      same.clear();
      other.clear();
      for (std::size_t j : near) {
        const double d = (surfels.positions[j] - p).norm();
        if (j == o || on_same_surface(surfels, o, j, thickness)) same.emplace_back(d, j);
        else if (d < reach) other.push_back(j);
      }
      std::sort(same.begin(), same.end());
      Eigen::Vector3d t1, t2;
      tangent_frame(normal, t1, t2);
      const double rotation = pattern_rotation(o);
      Row& row = rows[k];
      const auto& rings = quadrature.rings();
      for (std::size_t ring_index = 0; ring_index < rings.size(); ++ring_index) {
        const NearFieldRing& ring = rings[ring_index];
        const double share = 1.0 / static_cast<double>(ring.radii.size());
        const double offset = rotation + kGoldenFraction * static_cast<double>(ring_index);
        for (double rho : ring.radii) {
          const Rgb bent = NearFieldQuadrature::bend(dipole, rho, kappa);
          Rgb point;
          for (int c = 0; c < 3; ++c) point[c] = share * ring.node_weight[c] * bent[c];
          for (int a = 0; a < ring.nodes; ++a) {
            const double angle = 2.0 * kPi * (a + offset) / ring.nodes;
            const Eigen::Vector3d y =
                on_local_surface(p, normal, kappa, rho * (std::cos(angle) * t1 + std::sin(angle) * t2))
                    .position;
            // The nearest surfel of this surface owns the point; candidates are sorted by their
            // distance d from the receiver, and none with d > 2 |y - p| can beat the receiver.
            std::size_t owner = std::numeric_limits<std::size_t>::max();
            double best = r * r;  // a point farther than a disc radius from every surfel: none
            const double reach_out = 2.0 * rho + 1e-12;
            for (const auto& [d, j] : same) {
              if (d > reach_out && owner != std::numeric_limits<std::size_t>::max()) break;
              const double d2 = (y - surfels.positions[j]).squaredNorm();
              if (d2 < best || (d2 == best && j < owner)) {
                best = d2;
                owner = j;
              }
            }
            if (owner != std::numeric_limits<std::size_t>::max() &&
                !(whole_cells && (surfels.positions[owner] - p).norm() >= reach))
              row.add(static_cast<std::uint32_t>(owner), point);
          }
        }
      }
      const auto near_part = [&](double d) { return window.weight(d); };
      const auto far_part = [&](double d) { return 1.0 - window.weight(d); };
      for (std::size_t j : other) {
        if (!(area[j] > 0.0)) continue;
        const Eigen::Vector3d d = p - surfels.positions[j];
        // The other surface's material lies on its side away from the receiver.
        const Eigen::Vector3d nj = surfels.normals[j].dot(d) > 0.0
                                       ? Eigen::Vector3d(-surfels.normals[j])
                                       : surfels.normals[j];
        const Rgb w = whole_cells
                          ? cell_kernel(dipole, surfels.positions[j], nj, area[j], p,
                                        [](double) { return 1.0; })
                          : cell_kernel(dipole, surfels.positions[j], nj, area[j], p, near_part);
        row.add(static_cast<std::uint32_t>(j), w);
      }
      if (whole_cells) {
        for (const auto& [d, j] : same) {
          if (d >= reach || !(area[j] > 0.0)) continue;
          const Eigen::Vector3d nj = surfels.normals[j].dot(normal) < 0.0
                                         ? Eigen::Vector3d(-surfels.normals[j])
                                         : surfels.normals[j];
          row.add(static_cast<std::uint32_t>(j),
                  cell_kernel(dipole, surfels.positions[j], nj, area[j], p, far_part));
        }
      }
    }
  }
  NearFieldWeights out;
  out.first.resize(n + 1, 0);
  for (std::size_t k = 0; k < n; ++k)
    out.first[k + 1] = out.first[k] + static_cast<std::uint32_t>(rows[k].source.size());
  out.source.reserve(out.first[n]);
  out.weight.reserve(out.first[n]);
  for (Row& row : rows) {
    out.source.insert(out.source.end(), row.source.begin(), row.source.end());
    out.weight.insert(out.weight.end(), row.weight.begin(), row.weight.end());
  }
  return out;
}

}  // namespace sss
