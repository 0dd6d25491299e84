#include "surfel_cells.h"

#include <algorithm>
#include <cmath>

#include "cell_polygon.h"
#include "local_surface.h"

namespace sss {

bool on_same_surface(const LocalSurfels& surfels, std::size_t i, std::size_t j, double thickness) {
  const Eigen::Vector3d& n = surfels.normals[i];
  if (std::fabs(n.dot(surfels.normals[j])) < 0.5) return false;
  const Eigen::Vector3d d = surfels.positions[j] - surfels.positions[i];
  const double along = d.dot(n);
  const double height = along + 0.5 * surfels.curvature[i] * (d.squaredNorm() - along * along);
  return std::fabs(height) <= thickness;
}

SurfelCells surfel_cells(const LocalSurfels& surfels, const SurfelIndex& index,
                         const CancelFlag* cancel) {
  const std::size_t n = surfels.size();
  const double r = surfels.cell_radius;
  std::vector<Polygon> cells(n);
  const long count = static_cast<long>(n);
#pragma omp parallel default(none) shared(surfels, index, cells, count, r, cancel)
  {
    std::vector<std::size_t> near;
    std::vector<std::pair<double, Eigen::Vector2d>> neighbours;  // squared gap, plane point
    Polygon scratch;
#pragma omp for schedule(dynamic, 256)
    for (long i = 0; i < count; ++i) {
      if (cancelled(cancel)) continue;
      const Eigen::Vector3d& p = surfels.positions[i];
      Eigen::Vector3d t1, t2;
      tangent_frame(surfels.normals[i], t1, t2);
      const double thickness = surfels.thickness(i);
      Polygon& cell = cells[i];
      disc_polygon(Eigen::Vector2d::Zero(), surfels.disc_radius(i), cell);
      // Neighbours within 2r first; a cell that still reaches past r (a sparse spot of a random
      // sampling) asks again out to twice its reach, for the bisectors beyond r.
      double searched = 0.0;
      double reach2 = r * r;
      while (!cell.empty() && 4.0 * reach2 > searched * searched) {
        const double inner = searched;
        searched = std::max(2.0 * r, 2.0 * std::sqrt(reach2) * (1.0 + 1e-9));
        index.within(p, searched, near);
        neighbours.clear();
        bool owned = true;
        for (std::size_t j : near) {
          if (j == static_cast<std::size_t>(i) || !on_same_surface(surfels, i, j, thickness)) continue;
          const Eigen::Vector3d d = surfels.positions[j] - p;
          const Eigen::Vector2d q(d.dot(t1), d.dot(t2));
          if (q.squaredNorm() == 0.0) {
            if (j < static_cast<std::size_t>(i)) owned = false;  // a duplicate: the lower index owns
            continue;
          }
          if (d.norm() >= inner) neighbours.emplace_back(q.squaredNorm(), q);
        }
        if (!owned) {
          cell.clear();
          break;
        }
        // Nearest neighbours first: once a bisector lies beyond the polygon's farthest corner,
        // every later one does too.
        std::sort(neighbours.begin(), neighbours.end(),
                  [](const auto& a, const auto& b) { return a.first < b.first; });
        reach2 = 0.0;
        for (const Eigen::Vector2d& v : cell) reach2 = std::max(reach2, v.squaredNorm());
        for (const auto& [gap2, q] : neighbours) {
          if (0.25 * gap2 >= reach2) break;
          clip_to_nearer(cell, Eigen::Vector2d::Zero(), q, scratch);
          if (cell.empty()) break;
          reach2 = 0.0;
          for (const Eigen::Vector2d& v : cell) reach2 = std::max(reach2, v.squaredNorm());
        }
      }
    }
  }
  SurfelCells out;
  out.area.resize(n);
  out.first.resize(n + 1, 0);
  if (cancelled(cancel)) throw Cancelled();
  for (std::size_t i = 0; i < n; ++i) {
    out.area[i] = signed_area(cells[i]);
    out.first[i + 1] = out.first[i] + static_cast<std::uint32_t>(cells[i].size());
  }
  out.outline.reserve(out.first[n]);
  for (const Polygon& c : cells) out.outline.insert(out.outline.end(), c.begin(), c.end());
  return out;
}

}  // namespace sss
