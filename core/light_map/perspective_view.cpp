#include "perspective_view.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace sss {

namespace {
// tan(80 degrees): the widest half-angle one map covers.
constexpr double kMaxHalfTangent = 5.671281819617709;
}  // namespace

PerspectiveView PerspectiveView::fit_pixel(const std::vector<Eigen::Vector3d>& points,
                                           double radius, const Eigen::Vector3d& eye,
                                           double pixel_mm, int max_size) {
  PerspectiveView view;
  view.eye = eye;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto& p : points) centre += p;
  if (!points.empty()) centre /= static_cast<double>(points.size());
  const Eigen::Vector3d to_eye = eye - centre;
  if (!eye.allFinite() || !(to_eye.norm() > 0.0))
    throw std::invalid_argument("[sss::PerspectiveView] the light's position must be finite and "
                                "away from the points' centre");
  view.w = to_eye.normalized();
  view.v = perpendicular_up(view.w, Eigen::Vector3d::UnitZ());
  view.u = view.v.cross(view.w);
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d hi = -lo;
  view.nearest = std::numeric_limits<double>::infinity();
  for (const auto& p : points) {
    const Eigen::Vector3d d = p - eye;
    const double z = -d.dot(view.w);
    if (!(z > 2.0 * radius)) {
      std::ostringstream msg;
      msg << "[sss::PerspectiveView] a point light at (" << eye.transpose()
          << ") mm lies among the points (one is behind it or within two disc radii of it "
             "along its view): one light map cannot see them all";
      throw std::invalid_argument(msg.str());
    }
    const Eigen::Vector2d a(d.dot(view.u) / z, d.dot(view.v) / z);
    // A disc of radius r around p stays within r (z + |x|) / (z (z - r)) of p's image.
    const Eigen::Vector2d spread(radius * (z + std::fabs(d.dot(view.u))) / (z * (z - radius)),
                                 radius * (z + std::fabs(d.dot(view.v))) / (z * (z - radius)));
    lo = lo.cwiseMin(a - spread);
    hi = hi.cwiseMax(a + spread);
    view.nearest = std::min(view.nearest, z);
  }
  if (points.empty()) {
    lo = hi = Eigen::Vector2d::Zero();
    view.nearest = 1.0;
  }
  if (lo.minCoeff() < -kMaxHalfTangent || hi.maxCoeff() > kMaxHalfTangent) {
    std::ostringstream msg;
    msg << "[sss::PerspectiveView] a point light at (" << eye.transpose()
        << ") mm sees the points over more than 160 degrees: one light map cannot see them all";
    throw std::invalid_argument(msg.str());
  }
  const Eigen::Vector2d extent = hi - lo;
  const double needed = extent.maxCoeff() / std::max(1, max_size);
  view.pixel = std::max(pixel_mm / view.nearest, needed);
  if (!(view.pixel > 0.0)) view.pixel = 1.0;
  view.width = std::min(std::max(1, static_cast<int>(std::ceil(extent.x() / view.pixel))),
                        std::max(1, max_size));
  view.height = std::min(std::max(1, static_cast<int>(std::ceil(extent.y() / view.pixel))),
                         std::max(1, max_size));
  view.corner = lo;
  return view;
}

bool PerspectiveView::project(const Eigen::Vector3d& y, double& i, double& j) const {
  const Eigen::Vector3d d = y - eye;
  const double z = -d.dot(w);
  if (!(z > 0.0)) return false;
  i = (d.dot(u) / z - corner.x()) / pixel;
  j = (d.dot(v) / z - corner.y()) / pixel;
  return true;
}

Eigen::Vector3d PerspectiveView::ray(int i, int j) const {
  const double a = corner.x() + (i + 0.5) * pixel, b = corner.y() + (j + 0.5) * pixel;
  return (a * u + b * v - w).normalized();
}

DiscHits rasterize_discs(const PerspectiveView& view, const std::vector<Eigen::Vector3d>& positions,
                         const std::vector<Eigen::Vector3d>& normals, double radius,
                         const std::vector<double>& radii) {
  const std::size_t texels = static_cast<std::size_t>(view.width) * view.height;
  DiscHits hits;
  hits.surfel.assign(texels, -1);
  hits.depth.assign(texels, std::numeric_limits<double>::infinity());
  for (std::size_t s = 0; s < positions.size(); ++s) {
    const double r = radii.empty() ? radius : radii[s];
    const Eigen::Vector3d& p = positions[s];
    const Eigen::Vector3d& n = normals[s];
    const Eigen::Vector3d d = p - view.eye;
    const double z = -d.dot(view.w);
    int i0 = 0, i1 = view.width - 1, j0 = 0, j1 = view.height - 1;
    if (z > r) {  // else the disc may cover the whole map
      const double a = d.dot(view.u) / z, b = d.dot(view.v) / z;
      const double su = r * (z + std::fabs(d.dot(view.u))) / (z * (z - r));
      const double sv = r * (z + std::fabs(d.dot(view.v))) / (z * (z - r));
      i0 = std::max(i0, static_cast<int>(std::floor((a - su - view.corner.x()) / view.pixel)));
      i1 = std::min(i1, static_cast<int>(std::floor((a + su - view.corner.x()) / view.pixel)));
      j0 = std::max(j0, static_cast<int>(std::floor((b - sv - view.corner.y()) / view.pixel)));
      j1 = std::min(j1, static_cast<int>(std::floor((b + sv - view.corner.y()) / view.pixel)));
    }
    const double r2 = r * r;
    const double along_normal = d.dot(n);
    for (int j = j0; j <= j1; ++j) {
      for (int i = i0; i <= i1; ++i) {
        const Eigen::Vector3d ray = view.ray(i, j);
        const double rn = ray.dot(n);
        if (std::fabs(rn) < 1e-6) continue;
        const double t = along_normal / rn;  // eye + t ray meets the disc's plane
        if (!(t > 0.0)) continue;
        if ((view.eye + t * ray - p).squaredNorm() > r2) continue;
        const std::size_t k = static_cast<std::size_t>(j) * view.width + i;
        if (t < hits.depth[k]) {
          hits.depth[k] = t;
          hits.surfel[k] = static_cast<std::int32_t>(s);
        }
      }
    }
  }
  return hits;
}

}  // namespace sss
