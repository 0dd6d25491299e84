#include "near_field.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cell_polygon.h"
#include "local_surface.h"
#include "radial_kernel.h"
#include "surfel_cells.h"

namespace sss {
namespace {

constexpr double kPi = 3.14159265358979323846;

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

NearFieldWeights near_field_weights(const LocalSurfels& surfels, const SurfelCells& cells,
                                    const SurfelIndex& index, const Dipole& dipole, double reach,
                                    const std::vector<std::size_t>& receivers,
                                    const CancelFlag* cancel) {
  const std::size_t n = receivers.empty() ? surfels.size() : receivers.size();
  std::vector<Row> rows(n);
  const double r = surfels.cell_radius;
  const double kappa_limit = 1.0 / reach;
  // Cells of surfels within the reach extend beyond it by their farthest corner (about a disc
  // radius; more where a sparse spot's cell reaches to the disc that closes the surface).
  double cell_reach = 2.0 * r;
  for (const Eigen::Vector2d& v : cells.outline) cell_reach = std::max(cell_reach, v.norm());
  // The table need not reach past the kernel's support, where G has its final value: a few
  // huge cells (stray points of a scan) must not spread its samples too thin for the kernel.
  const double support = dipole.max_support_radius(kKernelSupportFraction);
  const RadialKernel kernel(dipole, std::min(reach + cell_reach, std::max(support, reach)),
                            kappa_limit);
  // An entry that carries less than the kernel's support fraction of its total in every
  // channel is left out, as the sources beyond the support are.
  Rgb negligible;
  for (int c = 0; c < 3; ++c)
    negligible[c] = kKernelSupportFraction * dipole.channel[c].total_diffuse_reflectance();
  const auto matters = [&negligible](const Rgb& w) {
    return w[0] > negligible[0] || w[1] > negligible[1] || w[2] > negligible[2];
  };
  const long count = static_cast<long>(n);
#pragma omp parallel default(none) shared(surfels, cells, index, dipole, receivers, rows, count, \
                                          r, reach, kappa_limit, kernel, matters, cancel)
  {
    std::vector<std::size_t> near, other;
    Polygon cell;
#pragma omp for schedule(dynamic, 64)
    for (long k = 0; k < count; ++k) {
      if (cancelled(cancel)) continue;
      const std::size_t o = receivers.empty() ? static_cast<std::size_t>(k) : receivers[k];
      const Eigen::Vector3d& p = surfels.positions[o];
      const Eigen::Vector3d& normal = surfels.normals[o];
      const double kappa = std::clamp(surfels.curvature[o], -kappa_limit, kappa_limit);
      const double thickness = surfels.thickness(o);
      index.within(p, reach, near);
      other.clear();
      Eigen::Vector3d t1, t2;
      tangent_frame(normal, t1, t2);
      Row& row = rows[k];
      for (std::size_t j : near) {
        if (j != o && !on_same_surface(surfels, o, j, thickness)) {
          other.push_back(j);
          continue;
        }
        if (cells.first[j] == cells.first[j + 1]) continue;
        // Surfel j's cell, from its own tangent frame into the receiver's.
        Eigen::Vector3d u1, u2;
        tangent_frame(surfels.normals[j], u1, u2);
        const Eigen::Vector3d offset = surfels.positions[j] - p;
        cell.clear();
        for (std::uint32_t v = cells.first[j]; v < cells.first[j + 1]; ++v) {
          const Eigen::Vector3d x = offset + cells.outline[v].x() * u1 + cells.outline[v].y() * u2;
          cell.emplace_back(x.dot(t1), x.dot(t2));
        }
        if (signed_area(cell) < 0.0) std::reverse(cell.begin(), cell.end());
        const Rgb w = kernel_over(cell, kernel, kappa);
        if (matters(w)) row.add(static_cast<std::uint32_t>(j), w);
      }
      for (std::size_t j : other) {
        if (cells.first[j] == cells.first[j + 1]) continue;
        // Surfel j's cell in its own plane, the receiver's foot on that plane at the origin;
        // the other surface's material lies on its side away from the receiver.
        Eigen::Vector3d u1, u2;
        tangent_frame(surfels.normals[j], u1, u2);
        const Eigen::Vector3d d = p - surfels.positions[j];
        const double height = std::fabs(d.dot(surfels.normals[j]));
        const Eigen::Vector2d foot(d.dot(u1), d.dot(u2));
        cell.clear();
        for (std::uint32_t v = cells.first[j]; v < cells.first[j + 1]; ++v)
          cell.push_back(cells.outline[v] - foot);
        const Rgb w = dipole_over(cell, dipole, height);
        if (matters(w)) row.add(static_cast<std::uint32_t>(j), w);
      }
    }
  }
  if (cancelled(cancel)) throw Cancelled();
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
