#include "splat_coverage.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "local_surface.h"
#include "surfel_index.h"

namespace sss {
namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr int kNeighbours = 16;
constexpr double kCornerMargin = 1.05;      // per-point radii reach 5 % past their cell

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// The signed area of triangle (origin, a, b) within distance r of the origin: the parts of
// the edge inside the circle span triangles, the parts outside span circular sectors.
double triangle_within(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double r) {
  const Eigen::Vector2d d = b - a;
  const double A = d.squaredNorm();
  if (A == 0.0) return 0.0;
  const auto sector = [r](const Eigen::Vector2d& p, const Eigen::Vector2d& q) {
    return 0.5 * r * r * std::atan2(cross2(p, q), p.dot(q));
  };
  const double B = a.dot(d), C = a.squaredNorm() - r * r;
  const double disc = B * B - A * C;
  if (disc <= 0.0) return sector(a, b);
  const double s = std::sqrt(disc);
  const double t1 = (-B - s) / A, t2 = (-B + s) / A;
  if (t2 <= 0.0 || t1 >= 1.0) return sector(a, b);
  const Eigen::Vector2d p = a + std::max(t1, 0.0) * d, q = a + std::min(t2, 1.0) * d;
  return sector(a, p) + 0.5 * cross2(p, q) + sector(q, b);
}

double polygon_area(const Polygon& polygon) {
  double twice = 0.0;
  for (std::size_t k = 0; k < polygon.size(); ++k)
    twice += cross2(polygon[k], polygon[(k + 1) % polygon.size()]);
  return 0.5 * twice;
}

double reach_of(const Polygon& polygon) {
  double reach2 = 0.0;
  for (const Eigen::Vector2d& v : polygon) reach2 = std::max(reach2, v.squaredNorm());
  return std::sqrt(reach2);
}

struct Cell {
  Polygon polygon;      // empty: open edge, a duplicate, or too few neighbours
  double spacing = 0;   // mean distance to the nearest kNeighbours
};

// Surfel i's Voronoi cell in its tangent plane among the neighbours on its own surface (normal
// within 60 degrees, height off the plane at most half the distance along it).
class CellBuilder {
 public:
  CellBuilder(const SurfelCloud& cloud, const SurfelIndex& index) : cloud_(cloud), index_(index) {}

  Cell build(std::size_t i) {
    Cell out;
    const Eigen::Vector3d& p = cloud_.positions[i];
    const Eigen::Vector3d& n = cloud_.normals[i];
    Eigen::Vector3d t1, t2;
    tangent_frame(n, t1, t2);
    index_.nearest(p, kNeighbours + 1, near_);
    double sum = 0.0;
    int count = 0;
    for (std::size_t j : near_) {
      if (j == i) continue;
      sum += (cloud_.positions[j] - p).norm();
      ++count;
    }
    out.spacing = count > 0 ? sum / count : 0.0;
    if (!gather(i, p, n, t1, t2, near_)) return out;
    const double far = std::sqrt(planar_.back().first);
    clip_cell(out.polygon, 2.0 * far);
    // The nearest neighbours close the cell only when no farther surfel can cut it.
    double reach = reach_of(out.polygon);
    if (2.0 * reach > far) {
      index_.within(p, 2.0 * reach, near_);
      if (!gather(i, p, n, t1, t2, near_)) {
        out.polygon.clear();
        return out;
      }
      clip_cell(out.polygon, 2.0 * far);
      reach = reach_of(out.polygon);
    }
    // An open edge, or a hole wider than the neighbourhood: the cell reaches past the
    // nearest neighbours. Else it ends where they do (their convex hull): at the edge of a
    // scan or of a hole in it, the surface does.
    if (reach >= far) {
      out.polygon.clear();
    } else {
      clip_to_hull(out.polygon);
    }
    return out;
  }

 private:
  // The planar offsets of the neighbours on i's surface, nearest first; false for a
  // duplicate that a lower index owns or for fewer than three neighbours.
  bool gather(std::size_t i, const Eigen::Vector3d& p, const Eigen::Vector3d& n,
              const Eigen::Vector3d& t1, const Eigen::Vector3d& t2,
              const std::vector<std::size_t>& candidates) {
    planar_.clear();
    for (std::size_t j : candidates) {
      if (j == i || std::fabs(n.dot(cloud_.normals[j])) < 0.5) continue;
      const Eigen::Vector3d d = cloud_.positions[j] - p;
      const Eigen::Vector2d q(d.dot(t1), d.dot(t2));
      if (q.squaredNorm() == 0.0) {
        if (j < i) return false;
        continue;
      }
      if (std::fabs(d.dot(n)) > 0.5 * q.norm()) continue;
      planar_.emplace_back(q.squaredNorm(), q);
    }
    std::sort(planar_.begin(), planar_.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    return planar_.size() >= 3;
  }

  void clip_cell(Polygon& cell, double half) {
    cell = {{-half, -half}, {half, -half}, {half, half}, {-half, half}};
    double reach2 = 2.0 * half * half;
    for (const auto& [gap2, q] : planar_) {
      if (0.25 * gap2 >= reach2) break;
      clip_to_nearer(cell, Eigen::Vector2d::Zero(), q, scratch_);
      if (cell.empty()) return;
      reach2 = 0.0;
      for (const Eigen::Vector2d& v : cell) reach2 = std::max(reach2, v.squaredNorm());
    }
  }

  // Keeps the part of the cell inside the convex hull of the surfel and its neighbours
  // (Andrew's monotone chain, counter-clockwise).
  void clip_to_hull(Polygon& cell) {
    points_.assign(1, Eigen::Vector2d::Zero());
    for (const auto& [gap2, q] : planar_) points_.push_back(q);
    std::sort(points_.begin(), points_.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
      return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
    });
    hull_.clear();
    for (int pass = 0; pass < 2; ++pass) {
      const std::size_t start = hull_.size();
      for (std::size_t k = 0; k < points_.size(); ++k) {
        const Eigen::Vector2d& q = pass == 0 ? points_[k] : points_[points_.size() - 1 - k];
        while (hull_.size() >= start + 2 &&
               cross2(hull_[hull_.size() - 1] - hull_[hull_.size() - 2], q - hull_[hull_.size() - 2]) <= 0.0)
          hull_.pop_back();
        hull_.push_back(q);
      }
      hull_.pop_back();
    }
    for (std::size_t k = 0; k < hull_.size() && !cell.empty(); ++k) {
      const Eigen::Vector2d d = hull_[(k + 1) % hull_.size()] - hull_[k];
      const Eigen::Vector2d outward(d.y(), -d.x());
      clip(cell, outward, outward.dot(hull_[k]), scratch_);
    }
  }

  const SurfelCloud& cloud_;
  const SurfelIndex& index_;
  std::vector<Eigen::Vector2d> points_, hull_;
  std::vector<std::size_t> near_;
  std::vector<std::pair<double, Eigen::Vector2d>> planar_;
  Polygon scratch_;
};

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  const std::size_t k = std::min(v.size() - 1, static_cast<std::size_t>(q * (v.size() - 1) + 0.5));
  std::nth_element(v.begin(), v.begin() + k, v.end());
  return v[k];
}
}  // namespace

double area_within(const Polygon& polygon, double r) {
  double sum = 0.0;
  for (std::size_t k = 0; k < polygon.size(); ++k)
    sum += triangle_within(polygon[k], polygon[(k + 1) % polygon.size()], r);
  return sum;
}

double SplatCoverage::uncovered(double r) const {
  double total = 0.0, within = 0.0;
  for (const Polygon& c : cells) {
    total += polygon_area(c);
    within += area_within(c, r);
  }
  return total > 0.0 ? std::max(0.0, 1.0 - within / total) : 0.0;
}

double SplatCoverage::radius_for(double target) const {
  double hi = 0.0;
  for (const Polygon& c : cells) hi = std::max(hi, reach_of(c));
  if (target <= 0.0) return hi;
  double lo = 0.0;
  for (int it = 0; it < 40 && hi - lo > 1e-6 * hi; ++it) {
    const double mid = 0.5 * (lo + hi);
    (uncovered(mid) <= target ? hi : lo) = mid;
  }
  return hi;
}

namespace {
SplatCoverage measure_with(const SurfelCloud& cloud, const SurfelIndex& index, std::size_t max_cells) {
  SplatCoverage out;
  const std::size_t n = cloud.size();
  if (n < 4) return out;
  const std::size_t measured = std::min(n, std::max<std::size_t>(max_cells, 1));
  std::vector<Cell> cells(measured);
  const long count = static_cast<long>(measured);
#pragma omp parallel default(none) shared(cloud, index, cells, count, n, measured)
  {
    CellBuilder builder(cloud, index);
#pragma omp for schedule(dynamic, 64)
    for (long k = 0; k < count; ++k) cells[k] = builder.build(static_cast<std::size_t>(k) * n / measured);
  }
  std::vector<double> spacing;
  for (Cell& c : cells) {
    if (c.spacing > 0.0) spacing.push_back(c.spacing);
    if (c.polygon.empty()) {
      ++out.open_edge;
    } else {
      out.cells.push_back(std::move(c.polygon));
    }
  }
  out.measured = out.cells.size();
  const double p10 = quantile(spacing, 0.1);
  out.spacing_spread = p10 > 0.0 ? quantile(spacing, 0.9) / p10 : 1.0;
  return out;
}

std::vector<double> cover_radii_with(const SurfelCloud& cloud, const SurfelIndex& index) {
  const std::size_t n = cloud.size();
  std::vector<double> radii(n, 0.0);
  if (n < 4) return radii;
  const long count = static_cast<long>(n);
#pragma omp parallel default(none) shared(cloud, index, radii, count)
  {
    CellBuilder builder(cloud, index);
#pragma omp for schedule(dynamic, 256)
    for (long i = 0; i < count; ++i) {
      const Cell c = builder.build(static_cast<std::size_t>(i));
      radii[i] = c.polygon.empty() ? 0.0 : kCornerMargin * reach_of(c.polygon);
    }
  }
  // Open edges and duplicates: the median of the closed neighbours', else the spacing.
  std::vector<double> filled = radii;
#pragma omp parallel default(none) shared(cloud, index, radii, filled, count)
  {
    std::vector<std::size_t> near;
    std::vector<double> around;
#pragma omp for schedule(dynamic, 256)
    for (long i = 0; i < count; ++i) {
      if (radii[i] > 0.0) continue;
      index.nearest(cloud.positions[i], kNeighbours + 1, near);
      around.clear();
      double spacing = 0.0;
      for (std::size_t j : near) {
        if (radii[j] > 0.0) around.push_back(radii[j]);
        spacing = std::max(spacing, (cloud.positions[j] - cloud.positions[i]).norm());
      }
      filled[i] = around.empty() ? spacing : quantile(around, 0.5);
    }
  }
  return filled;
}

}  // namespace

SplatCoverage measure_splat_coverage(const SurfelCloud& cloud, std::size_t max_cells) {
  if (cloud.size() < 4) return {};
  return measure_with(cloud, SurfelIndex(cloud.positions), max_cells);
}

std::vector<double> per_point_cover_radii(const SurfelCloud& cloud) {
  if (cloud.size() < 4) return std::vector<double>(cloud.size(), 0.0);
  return cover_radii_with(cloud, SurfelIndex(cloud.positions));
}

SplatRadii choose_splat_radii(const SurfelCloud& cloud, SplatRadiusMode mode, double coverage_target,
                              double scale) {
  if (!(coverage_target >= 0.0 && coverage_target < 1.0))
    throw std::invalid_argument("coverage target " + std::to_string(coverage_target) +
                                " is not an uncovered area fraction in [0, 1)");
  if (!(scale > 0.0) || !std::isfinite(scale))
    throw std::invalid_argument("splat radius scale " + std::to_string(scale) + " is not positive");
  SplatRadii out;
  if (cloud.size() < 2) {
    out.radius = out.view_radius = scale;  // nothing to measure: one scene unit
    return out;
  }
  const SurfelIndex index(cloud.positions);  // one k-d tree for the coverage, radii and spacing
  const SplatCoverage coverage = measure_with(cloud, index, 20000);
  out.spacing_spread = coverage.spacing_spread;
  // Automatic: per point where the spacing spreads, or where a few cells far larger than the
  // rest would set the uniform radius (a random sampling's tail has r(1e-4) / r(0.05) = 1.75).
  const bool tail = coverage.measured > 0 &&
                    coverage.radius_for(coverage_target) > kPerPointTail * coverage.radius_for(0.05);
  const bool per_point = mode == SplatRadiusMode::PerPoint ||
                         (mode == SplatRadiusMode::Automatic && (coverage.spacing_spread > kPerPointSpread || tail));
  const double spacing = mean_spacing(cloud.positions, index);
  if (coverage.measured == 0) {
    // No closed cell (a line, a handful of points): 1.5 mean spacings, else 1 % of the extent.
    const double extent = cloud.bounds().extent().norm();
    out.radius = scale * (spacing > 0.0 ? kCellSpacings * spacing : (extent > 0.0 ? 0.01 * extent : 1.0));
    out.view_radius = out.radius;
    return out;
  }
  out.radius = scale * kCellSpacings * spacing;
  if (per_point) {
    out.per_point = cover_radii_with(cloud, index);
    for (double& r : out.per_point) r *= scale;
    out.view_radius = quantile(out.per_point, 0.5);
    out.view_uncovered = 0.0;
  } else {
    out.view_radius = scale * coverage.radius_for(coverage_target);
    out.view_uncovered = coverage.uncovered(out.view_radius);
  }
  return out;
}

SplatRadii assign_splat_radii(SurfelCloud& cloud, SplatRadiusMode mode, double coverage_target,
                              double scale) {
  SplatRadii radii = choose_splat_radii(cloud, mode, coverage_target, scale);
  cloud.radius = radii.radius;
  cloud.radii = radii.per_point_chosen() ? radii.per_point
                                         : std::vector<double>(cloud.size(), radii.view_radius);
  return radii;
}

}  // namespace sss
