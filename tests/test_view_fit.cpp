// The automatic camera (core/view/view_fit.h): it holds the asked fraction of the points, centred,
// fills the frame along its limiting axis, and a few far strays do not shrink the surface.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "view_fit.h"

namespace sss {
namespace {
constexpr double kPi = 3.14159265358979323846;

// Image coordinates in [-1, 1] of p (x over the half width, y over the half height).
Eigen::Vector2d project(const ViewFit& fit, const ViewFitRequest& r, const Eigen::Vector3d& p) {
  const Eigen::Vector3d w = (fit.position - fit.focal_point).normalized();
  const Eigen::Vector3d u = r.up.cross(w).normalized(), v = w.cross(u);
  const Eigen::Vector3d d = p - fit.position;
  if (r.orthographic)
    return {u.dot(d) / (fit.parallel_scale * r.aspect), v.dot(d) / fit.parallel_scale};
  const double depth = -w.dot(d), t = std::tan(0.5 * r.view_angle_degrees * kPi / 180.0);
  return {u.dot(d) / (depth * t * r.aspect), v.dot(d) / (depth * t)};
}

// A floor 4 m wide from 0.5 m to 3 m in front of a camera at the origin looking along +z (a
// Kinect-like frame tilted down), plus `strays` points scattered up to 50 m away.
std::vector<Eigen::Vector3d> floor_scene(int strays) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 20000; ++i)
    points.emplace_back(-2.0 + 4.0 * unit(rng), 0.8 + 0.3 * unit(rng), 0.5 + 2.5 * unit(rng));
  for (int i = 0; i < strays; ++i)
    points.emplace_back(100.0 * unit(rng) - 50.0, 100.0 * unit(rng) - 50.0, 50.0 * unit(rng));
  return points;
}

void expect_framed(const std::vector<Eigen::Vector3d>& points, std::size_t surface,
                   const ViewFitRequest& request) {
  const ViewFit fit = fit_view(points, request);
  std::size_t inside = 0;
  double x_lo = 1e9, x_hi = -1e9, y_lo = 1e9, y_hi = -1e9;
  for (std::size_t i = 0; i < surface; ++i) {
    const Eigen::Vector2d q = project(fit, request, points[i]);
    inside += std::abs(q.x()) <= 1.0 && std::abs(q.y()) <= 1.0;
    x_lo = std::min(x_lo, q.x()), x_hi = std::max(x_hi, q.x());
    y_lo = std::min(y_lo, q.y()), y_hi = std::max(y_hi, q.y());
  }
  std::printf("[ fit ] %s: %.2f %% of the surface inside, spans x %.2f..%.2f, y %.2f..%.2f\n",
              request.orthographic ? "orthographic" : "perspective",
              100.0 * inside / surface, x_lo, x_hi, y_lo, y_hi);
  EXPECT_GE(static_cast<double>(inside), 0.99 * surface);
  // Centred, and filling the frame but for the margin along the limiting axis (the 1 % left
  // out may lie a little beyond it).
  const double fill = std::max(x_hi - x_lo, y_hi - y_lo) / 2.0;
  EXPECT_GT(fill, 0.9);
  EXPECT_LT(fill, 1.1);
  EXPECT_NEAR(x_lo + x_hi, 0.0, 0.1);
  EXPECT_NEAR(y_lo + y_hi, 0.0, 0.1);
}

TEST(ViewFit, FramesTheSurfaceDespiteStrays) {
  const std::vector<Eigen::Vector3d> points = floor_scene(100);  // 0.5 % strays
  ViewFitRequest request;
  request.view_dir = Eigen::Vector3d(0, 0, -1);  // the camera on the sensor's side
  request.up = Eigen::Vector3d(0, -1, 0);
  request.aspect = 4.0 / 3.0;
  expect_framed(points, 20000, request);
  request.orthographic = true;
  expect_framed(points, 20000, request);
}

TEST(ViewFit, AllPointsWithFractionOne) {
  const std::vector<Eigen::Vector3d> points = floor_scene(0);
  ViewFitRequest request;
  request.view_dir = Eigen::Vector3d(0.3, -1, 0.5);
  request.up = Eigen::Vector3d(0, 0, 1);
  request.fraction = 1.0;
  request.margin = 0.0;
  const ViewFit fit = fit_view(points, request);
  double largest = 0.0;
  for (const Eigen::Vector3d& p : points) largest = std::max(largest, project(fit, request, p).cwiseAbs().maxCoeff());
  EXPECT_LE(largest, 1.0 + 1e-9);
  EXPECT_GT(largest, 0.999);
}

TEST(ViewFit, WholeObjectIsNotCropped) {
  // A closed object without strays: the frame of every point is barely farther than that of
  // 99 % of them, so every point is framed.
  std::mt19937 rng(9);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 20000; ++i) {
    const Eigen::Vector3d g(gauss(rng), gauss(rng), gauss(rng));
    points.push_back(Eigen::Vector3d(30.0, 10.0, 10.0).cwiseProduct(g.normalized()));
  }
  for (const bool orthographic : {false, true}) {
    ViewFitRequest request;
    request.view_dir = Eigen::Vector3d(0, -1, 0.6);
    request.up = Eigen::Vector3d(0, 0, 1);
    request.orthographic = orthographic;
    const ViewFit fit = fit_view(points, request);
    double largest = 0.0;
    for (const Eigen::Vector3d& p : points)
      largest = std::max(largest, project(fit, request, p).cwiseAbs().maxCoeff());
    EXPECT_LE(largest, 1.0 - 0.99 * request.margin) << (orthographic ? "orthographic" : "perspective");
    EXPECT_GT(largest, 0.9);
  }
}

TEST(ViewFit, Refusals) {
  ViewFitRequest request;
  EXPECT_THROW(fit_view({}, request), std::invalid_argument);
  request.up = request.view_dir;
  EXPECT_THROW(fit_view({{0, 0, 0}}, request), std::invalid_argument);
  request = ViewFitRequest{};
  request.fraction = 0.0;
  EXPECT_THROW(fit_view({{0, 0, 0}}, request), std::invalid_argument);
  request = ViewFitRequest{};
  const ViewFit one = fit_view({{1, 2, 3}}, request);  // one point: any frame around it
  EXPECT_TRUE(one.position.allFinite());
  EXPECT_GT((one.position - one.focal_point).norm(), 0.0);
}

}  // namespace
}  // namespace sss
