// The automatic camera: looking along a given direction, the nearest position (or the smallest
// orthographic scale) whose frame holds a given fraction of the points, centred on them, or
// all of them when that is not much farther. Fitted
// to every point, as VTK's ResetCamera does (a bounding sphere of the bounds), a scan's stray
// returns and far rows leave its surface a small patch in the middle of the image; fitted to
// 99 % of the points, a Kinect frame or a room fills it.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace sss {

struct ViewFit {
  Eigen::Vector3d focal_point{Eigen::Vector3d::Zero()};
  Eigen::Vector3d position{Eigen::Vector3d::UnitZ()};
  double parallel_scale = 1.0;  // orthographic: half the frame's height
};

struct ViewFitRequest {
  Eigen::Vector3d view_dir{0, 0, 1};  // from the points towards the camera
  Eigen::Vector3d up{0, 1, 0};
  double view_angle_degrees = 30.0;   // vertical, as vtkCamera's
  double aspect = 1.0;                // width over height
  bool orthographic = false;
  double fraction = 0.99;             // of the points inside the frame, in (0, 1]
  double margin = 0.05;               // of the frame left free on each side
  // Every point is framed when that takes at most this times the distance (orthographic: the
  // scale) of the frame holding `fraction` of them: a whole object is not cropped, a scan's
  // strays do not shrink it.
  double whole_tolerance = 1.1;
};

// Throws std::invalid_argument for no points, a view direction along `up` or of zero length, a
// fraction outside (0, 1] or a view angle outside (0, 180).
ViewFit fit_view(const std::vector<Eigen::Vector3d>& points, const ViewFitRequest& request);

}  // namespace sss
