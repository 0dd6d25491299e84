#include <Eigen/Geometry>
#include "disc_raster.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace sss {

Eigen::Vector3d perpendicular_up(const Eigen::Vector3d& w, const Eigen::Vector3d& up) {
  Eigen::Vector3d v = up - up.dot(w) * w;
  if (v.norm() < 1e-6 * std::max(1.0, up.norm())) {
    const Eigen::Vector3d axis = std::fabs(w.z()) < 0.9 ? Eigen::Vector3d::UnitZ()
                                                         : Eigen::Vector3d::UnitY();
    v = axis - axis.dot(w) * w;
  }
  return v.normalized();
}

namespace {

struct PlaneBox {
  OrthoView view;
  Eigen::Vector2d lo, hi;
};

PlaneBox plane_box(const std::vector<Eigen::Vector3d>& points, double radius,
                   const Eigen::Vector3d& w, const Eigen::Vector3d& up) {
  PlaneBox box;
  box.view.w = w.normalized();
  box.view.v = perpendicular_up(box.view.w, up);
  box.view.u = box.view.v.cross(box.view.w);
  box.lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  box.hi = -box.lo;
  for (const auto& p : points) {
    const Eigen::Vector2d q(p.dot(box.view.u), p.dot(box.view.v));
    box.lo = box.lo.cwiseMin(q);
    box.hi = box.hi.cwiseMax(q);
  }
  if (points.empty()) box.lo = box.hi = Eigen::Vector2d::Zero();
  box.lo.array() -= radius;
  box.hi.array() += radius;
  return box;
}

}  // namespace

OrthoView OrthoView::fit_pixel(const std::vector<Eigen::Vector3d>& points, double radius,
                               const Eigen::Vector3d& w, const Eigen::Vector3d& up,
                               double pixel, int max_size) {
  PlaneBox box = plane_box(points, radius, w, up);
  const Eigen::Vector2d extent = box.hi - box.lo;
  const double needed = extent.maxCoeff() / std::max(1, max_size);
  box.view.pixel = std::max(pixel, needed);
  if (!(box.view.pixel > 0.0)) box.view.pixel = 1.0;
  box.view.width = std::max(1, static_cast<int>(std::ceil(extent.x() / box.view.pixel)));
  box.view.height = std::max(1, static_cast<int>(std::ceil(extent.y() / box.view.pixel)));
  box.view.width = std::min(box.view.width, std::max(1, max_size));
  box.view.height = std::min(box.view.height, std::max(1, max_size));
  box.view.corner = box.lo;
  return box.view;
}

OrthoView OrthoView::fit_image(const std::vector<Eigen::Vector3d>& points, double radius,
                               const Eigen::Vector3d& w, const Eigen::Vector3d& up, int width,
                               int height) {
  if (width <= 0 || height <= 0)
    throw std::invalid_argument("[sss::OrthoView::fit_image] image size must be positive");
  PlaneBox box = plane_box(points, radius, w, up);
  const Eigen::Vector2d extent = box.hi - box.lo;
  const double margin = 1.05;
  box.view.pixel = margin * std::max(extent.x() / width, extent.y() / height);
  if (!(box.view.pixel > 0.0)) box.view.pixel = 1.0;
  box.view.width = width;
  box.view.height = height;
  const Eigen::Vector2d centre = 0.5 * (box.lo + box.hi);
  box.view.corner = centre - 0.5 * box.view.pixel * Eigen::Vector2d(width, height);
  return box.view;
}

DiscHits rasterize_discs(const OrthoView& view, const std::vector<Eigen::Vector3d>& positions,
                         const std::vector<Eigen::Vector3d>& normals, double radius,
                         const std::vector<double>& radii) {
  const std::size_t pixels = static_cast<std::size_t>(view.width) * view.height;
  DiscHits hits;
  hits.surfel.assign(pixels, -1);
  hits.depth.assign(pixels, -std::numeric_limits<double>::infinity());
  for (std::size_t s = 0; s < positions.size(); ++s) {
    const double r = radii.empty() ? radius : radii[s];
    const double r2 = r * r;
    const Eigen::Vector3d& p = positions[s];
    const Eigen::Vector3d& n = normals[s];
    const double nw = n.dot(view.w);
    if (std::fabs(nw) < 1e-6) continue;
    // The disc's outline on the image plane is an ellipse inside this box.
    const double half_u = r * std::sqrt(std::max(0.0, 1.0 - n.dot(view.u) * n.dot(view.u)));
    const double half_v = r * std::sqrt(std::max(0.0, 1.0 - n.dot(view.v) * n.dot(view.v)));
    const double pu = p.dot(view.u) - view.corner.x();
    const double pv = p.dot(view.v) - view.corner.y();
    const int i0 = std::max(0, static_cast<int>(std::floor((pu - half_u) / view.pixel)));
    const int i1 = std::min(view.width - 1, static_cast<int>(std::floor((pu + half_u) / view.pixel)));
    const int j0 = std::max(0, static_cast<int>(std::floor((pv - half_v) / view.pixel)));
    const int j1 = std::min(view.height - 1, static_cast<int>(std::floor((pv + half_v) / view.pixel)));
    for (int j = j0; j <= j1; ++j) {
      for (int i = i0; i <= i1; ++i) {
        const Eigen::Vector3d q = view.pixel_center(i, j);
        const double t = (p - q).dot(n) / nw;  // ray q + t w meets the disc's plane
        const Eigen::Vector3d x = q + t * view.w;
        if ((x - p).squaredNorm() > r2) continue;
        const std::size_t k = static_cast<std::size_t>(j) * view.width + i;
        if (t > hits.depth[k]) {
          hits.depth[k] = t;
          hits.surfel[k] = static_cast<std::int32_t>(s);
        }
      }
    }
  }
  return hits;
}

}  // namespace sss
