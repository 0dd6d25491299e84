#include "view_fit.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sss {
namespace {

// The value below which `fraction` of the values lie (they are reordered).
double quantile(std::vector<double>& values, double fraction) {
  const double at = std::floor(fraction * static_cast<double>(values.size() - 1) + 0.5);
  const std::size_t k = std::min(values.size() - 1, static_cast<std::size_t>(std::max(at, 0.0)));
  std::nth_element(values.begin(), values.begin() + static_cast<long>(k), values.end());
  return values[k];
}

// Along one image axis (coordinate a of each point, depth behind the front plane `behind`):
// the centre c and front-plane distance D that hold `fraction` of the points within
// |a - c| <= t (D + behind), the smallest D: D = max(R - c / t, L + c / t) with R and L the
// quantiles of a / t - behind and -a / t - behind, least where the two meet.
void fit_axis(const std::vector<double>& a, const std::vector<double>& behind, double t,
              double fraction, double& centre, double& distance) {
  std::vector<double> right(a.size()), left(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    right[i] = a[i] / t - behind[i];
    left[i] = -a[i] / t - behind[i];
  }
  const double R = quantile(right, fraction), L = quantile(left, fraction);
  centre = 0.5 * t * (R - L);
  distance = 0.5 * (R + L);
}

struct Axes {
  Eigen::Vector3d u, v, w;  // image right, image up, towards the camera
};

// The frame holding `inside` of the points along each side of each axis (a, b, c: their
// coordinates along u, v, w).
ViewFit frame(const std::vector<double>& a, const std::vector<double>& b,
              const std::vector<double>& c, const Axes& axes, const ViewFitRequest& request,
              double inside) {
  const Eigen::Vector3d &u = axes.u, &v = axes.v, &w = axes.w;
  std::vector<double> sorted = c;
  const double front = quantile(sorted, inside);
  const double middle = quantile(sorted, 0.5);
  const double back = quantile(sorted, 1.0 - inside);
  std::vector<double> behind(c.size());
  for (std::size_t i = 0; i < c.size(); ++i) behind[i] = front - c[i];

  ViewFit fit;
  double cu = 0.0, cv = 0.0;
  const double keep = 1.0 - request.margin;
  if (request.orthographic) {  // an orthographic frame: the same as an infinitely far camera
    std::vector<double> flat(c.size(), 0.0);
    double du = 0.0, dv = 0.0;
    fit_axis(a, flat, 1.0, inside, cu, du);
    fit_axis(b, flat, 1.0, inside, cv, dv);
    fit.parallel_scale = std::max({dv, du / request.aspect, 1e-12}) / keep;
    const double depth = std::max(front - back, fit.parallel_scale);
    fit.focal_point = cu * u + cv * v + middle * w;
    fit.position = cu * u + cv * v + (front + depth) * w;
    return fit;
  }
  const double t_v = std::tan(0.5 * request.view_angle_degrees * M_PI / 180.0) * keep;
  const double t_u = t_v * request.aspect;
  double du = 0.0, dv = 0.0;
  fit_axis(a, behind, t_u, inside, cu, du);
  fit_axis(b, behind, t_v, inside, cv, dv);
  // In front of the front plane by at least a hundredth of the points' depth and width.
  const double extent = std::max(front - back, std::max(std::abs(du), std::abs(dv)) * t_v);
  const double distance = std::max({du, dv, 0.01 * extent, 1e-12});
  fit.position = cu * u + cv * v + (front + distance) * w;
  fit.focal_point = cu * u + cv * v + std::min(middle, front) * w;
  if ((fit.position - fit.focal_point).norm() <= 0.0) fit.focal_point = fit.position - w;
  return fit;
}

// How large the frame is: its orthographic scale, or the distance from the camera to the
// points' median depth.
double scale_of(const ViewFit& fit, const ViewFitRequest& request) {
  return request.orthographic ? fit.parallel_scale : (fit.position - fit.focal_point).norm();
}

}  // namespace

ViewFit fit_view(const std::vector<Eigen::Vector3d>& points, const ViewFitRequest& request) {
  if (points.empty()) throw std::invalid_argument("fit_view: no points");
  if (!(request.fraction > 0.0 && request.fraction <= 1.0))
    throw std::invalid_argument("fit_view: the fraction must be in (0, 1]");
  if (!(request.view_angle_degrees > 0.0 && request.view_angle_degrees < 180.0))
    throw std::invalid_argument("fit_view: the view angle must be in (0, 180) degrees");
  if (!(request.view_dir.norm() > 0.0))
    throw std::invalid_argument("fit_view: the view direction has zero length");
  const Eigen::Vector3d w = request.view_dir.normalized();
  const Eigen::Vector3d side = request.up.cross(w);
  if (!(side.norm() > 1e-9 * request.up.norm()))
    throw std::invalid_argument("fit_view: the view direction runs along the up vector");
  const Eigen::Vector3d u = side.normalized(), v = w.cross(u);

  // At most 64 k points looked at.
  const std::size_t stride = std::max<std::size_t>(1, points.size() / 65536);
  std::vector<double> a, b, c;
  for (std::size_t i = 0; i < points.size(); i += stride) {
    a.push_back(u.dot(points[i]));
    b.push_back(v.dot(points[i]));
    c.push_back(w.dot(points[i]));
  }
  const Axes axes{u, v, w};
  const ViewFit whole = frame(a, b, c, axes, request, 1.0);
  if (request.fraction >= 1.0) return whole;
  // Half the fraction left out on each side of each axis.
  const ViewFit robust = frame(a, b, c, axes, request, 1.0 - 0.5 * (1.0 - request.fraction));
  return scale_of(whole, request) <= request.whole_tolerance * scale_of(robust, request) ? whole
                                                                                       : robust;
}

}  // namespace sss
