// The surface a scan measured, not its noise: each point is moved onto a smooth surface fitted
// to its neighbours, and its normal is that surface's, over a neighbourhood sized from the
// noise measured there.
//
// Around a point p, in a frame (t1, t2, n) of a first normal, the neighbours' heights
// h_j = (q_j - p) . n over their tangential offsets (x_j, y_j) are fitted by least squares
// with the quadric (moving least squares, order 2)
//   h(x, y) = a + b x + c y + d x^2 + e x y + f y^2,
// the neighbours weighted by Tukey's biweight of their residual, w = (1 - (r / tau)^2)^2 for
// |r| < tau: first planes with tau halved each round from half the neighbourhood's radius (so
// that the fit settles on the point's own face), then quadrics with tau = 4.685 sigma, then one
// fit that weighs every neighbour within tau alike. The neighbours are the nearest along the
// tangent plane, heights within tau counted as on it (3D nearest neighbours of a noisy point
// favour those at its own height). The point moves to p + a n and its normal becomes
// normalize(n - b t1 - c t2), with the slope (b, c) of the plane fitted over the same
// neighbours instead where the two slopes differ by less than the noise of their difference
// (a Hausman test): at a scan's open edge, whose neighbours lie on one side, the quadric's slope
// extrapolates (within one spacing of a noisy plane's edge, mean tilt 4.9 degrees with it, 1.8
// with this, at noise of 0.3 spacings).
//
// The noise sigma is the residuals' RMS (over k - 6 degrees of freedom) of a first fit over
// `noise_neighbours`, then the median of that over the same neighbours (one rough patch does
// not make its surroundings noisy). A plane fit over k points of mean density rho tilts by
// 2 sigma sqrt(pi rho) / k radians per axis, 1.25 times that on average, so each point's
// second fit takes
//   k = 2.5 sigma sqrt(pi rho) / normal_tolerance
// nearest neighbours, clamped to [noise_neighbours, max_neighbours]: a flat wall of a Kinect at
// 2 m (3.4 mm pitch, 3.4 mm noise) takes about 200 at the default tolerance, a clean scan 24.
// The second fit starts in the frame of the point's first normal; where under a quarter of its
// neighbours' first normals share that one (within 30 degrees: with noise of one spacing, a
// first fit's 24 points are about as thick as they are wide, and one in a few thousand comes out
// about 90 degrees wrong, which a fit in that frame does not undo), it is also fitted in the
// frame most of them share, and the fit with the smaller residuals is kept.
// Measured (tests/test_denoised_surface.cpp): the noise within 10 %, heights left at
// 0.2-0.4 sigma, mean tilt 1.2-1.8 degrees (the quadric's slope varies more than a plane's).
// A fit whose neighbours reach another face leans towards it. So, where some of a point's
// neighbours have normals over 30 degrees from its own, it is fitted again over the neighbours
// whose normals lie within 30 degrees of the plane through it that its neighbours support best
// (its own, or a neighbour's clearly better supported), in two rounds.
// Measured (tests/test_denoised_surface.cpp, a box's 90 degree edge, convex and concave): at
// noise up to 0.3 spacings the normals farther than one spacing from the edge within 3 degrees
// of their face's on average and 6 at the 99th percentile (the largest 7; up to 44 before); at
// noise of one spacing, where the fits reach 8 spacings, some points up to 4 spacings from the
// edge take the other face's normal and those beyond lean by up to 4 degrees on average. Not
// met yet: where points lie far apart a crease's points move off it (5 cm at the synthetic
// room's far corners, 6 cm spacing).
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

#include "progress.h"

namespace sss {

struct DenoiseSettings {
  bool enabled = true;
  int noise_neighbours = 24;
  int max_neighbours = 256;
  double normal_tolerance = 0.02;  // radians: the normal's standard error the fit is sized for
  // Throws std::invalid_argument naming the value: noise_neighbours below 8, max_neighbours
  // below it or over 1024, a tolerance not in (0, 0.5].
  void check() const;
};

struct DenoisedSurface {
  std::vector<Eigen::Vector3d> positions;  // on the fitted surface
  std::vector<Eigen::Vector3d> normals;    // unit, the sign arbitrary (orient them after);
                                           // zero where the neighbours span no plane
  std::vector<float> noise;                // sigma, units of the positions
  std::vector<int> neighbours;             // how many the second fit took
};

struct DenoiseReport {
  std::size_t points = 0;
  double median_noise = 0.0, p90_noise = 0.0;  // units of the positions
  double median_spacing = 0.0;                 // distance to the nearest other point
  int median_neighbours = 0, largest_neighbours = 0;
  double largest_shift = 0.0;  // farthest a point moved
  std::size_t beside_crease = 0;  // points fitted again over their own face's neighbours
  std::size_t in_neighbours_frame = 0;  // points whose fit in their neighbours' frame was kept
  // "noise 1.2 (p90 3.1) at spacing 3.4, fits of 177 points (largest 256), largest shift 17.8,
  // 5120 beside a crease, 3 fitted in their neighbours' frame"
  std::string summary() const;
};

// Disabled, or with fewer than noise_neighbours + 1 points: the positions as given, zero
// normals, zero noise. Progress counts both fits' points.
DenoisedSurface denoise_surface(const std::vector<Eigen::Vector3d>& positions,
                                const DenoiseSettings& settings, DenoiseReport* report = nullptr,
                                const Progress& progress = {});

}  // namespace sss
