// A point light's view of the surfels: rays from one point (the eye) through the texels of an
// image plane at unit distance, with a depth test on the discs along each ray. The orthographic
// view of a directional light is disc_raster.h's.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "disc_raster.h"

namespace sss {

struct PerspectiveView {
  Eigen::Vector3d eye{0, 0, 0};            // mm
  Eigen::Vector3d u{1, 0, 0}, v{0, 1, 0};  // image axes
  Eigen::Vector3d w{0, 0, 1};              // from the scene towards the eye; rays run along -w
  double pixel = 1.0;                      // texel edge on the plane at unit distance
  Eigen::Vector2d corner{0, 0};            // that plane's coordinates of the lower-left corner
  int width = 0, height = 0;
  double nearest = 0;                      // distance along -w of the nearest point fitted (mm)

  // A view from `eye` that sees every disc (points with radius `radius`), its texels `pixel_mm`
  // wide at the nearest point, enlarged so neither side exceeds max_size. Throws
  // std::invalid_argument when the eye lies among the points: a point within two disc radii of
  // the eye's image plane, or a field of view over 160 degrees, needs more than one map.
  static PerspectiveView fit_pixel(const std::vector<Eigen::Vector3d>& points, double radius,
                                   const Eigen::Vector3d& eye, double pixel_mm, int max_size);

  // The texel y falls in, as continuous coordinates; false behind the eye.
  bool project(const Eigen::Vector3d& y, double& i, double& j) const;
  // The unit direction from the eye through the centre of texel (i, j).
  Eigen::Vector3d ray(int i, int j) const;
};

// For each texel: the nearest disc along its ray (-1 where none) and its distance from the eye
// (mm). Discs nearly edge-on to a ray cover no texel there.
DiscHits rasterize_discs(const PerspectiveView& view, const std::vector<Eigen::Vector3d>& positions,
                         const std::vector<Eigen::Vector3d>& normals, double radius,
                         const std::vector<double>& radii = {});

}  // namespace sss
