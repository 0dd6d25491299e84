// Orthographic rasterisation of surfel discs with a depth test: the light's view for the
// illumination map and the camera's view for images share it.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "surfel_cloud.h"

namespace sss {

struct OrthoView {
  Eigen::Vector3d u{1, 0, 0}, v{0, 1, 0};  // image axes
  Eigen::Vector3d w{0, 0, 1};              // towards the viewer (or the light)
  double pixel = 1.0;                      // pixel (texel) edge, mm
  Eigen::Vector2d corner{0, 0};            // plane coordinates of the image's lower-left corner
  int width = 0, height = 0;

  // View along -w fitted to the discs' bounds; `up` picks v (any vector not parallel to w).
  // Pixel size is `pixel`, enlarged so neither side exceeds max_size.
  static OrthoView fit_pixel(const std::vector<Eigen::Vector3d>& points, double radius,
                             const Eigen::Vector3d& w, const Eigen::Vector3d& up, double pixel,
                             int max_size);
  // View along -w with a fixed image size, the discs' bounds centred with a small margin.
  static OrthoView fit_image(const std::vector<Eigen::Vector3d>& points, double radius,
                             const Eigen::Vector3d& w, const Eigen::Vector3d& up, int width,
                             int height);
  // Centre of pixel (i, j) on the plane through the local origin.
  Eigen::Vector3d pixel_center(int i, int j) const {
    return (corner.x() + (i + 0.5) * pixel) * u + (corner.y() + (j + 0.5) * pixel) * v;
  }
};

// For each pixel: the nearest disc along -w (-1 where none) and the hit's height along w.
struct DiscHits {
  std::vector<std::int32_t> surfel;
  std::vector<double> depth;
  Eigen::Vector3d hit_point(const OrthoView& view, int i, int j) const {
    return view.pixel_center(i, j) + depth[static_cast<std::size_t>(j) * view.width + i] * view.w;
  }
};

// Discs nearly edge-on (|n.w| < 1e-6) cover no pixel. Each disc has its own radius in `radii`
// when that is not empty, else `radius`.
DiscHits rasterize_discs(const OrthoView& view, const std::vector<Eigen::Vector3d>& positions,
                         const std::vector<Eigen::Vector3d>& normals, double radius,
                         const std::vector<double>& radii = {});

// A unit vector perpendicular to w, as close to `up` as possible.
Eigen::Vector3d perpendicular_up(const Eigen::Vector3d& w, const Eigen::Vector3d& up);

}  // namespace sss
