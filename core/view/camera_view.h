// The camera view on the CPU (step 3): surfel discs splatted orthographically with a depth
// test, each pixel showing Lo = Ft(eta, wo) B of the disc it sees (eq. 14).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "linear_image.h"
#include "surfel_cloud.h"

namespace sss {

struct OrthoCamera {
  Eigen::Vector3d view_direction{0, 0, 1};  // from the object towards the camera
  Eigen::Vector3d up{0, 1, 0};
  int width = 512, height = 512;
};

// Lo for each surfel seen along view_direction: Ft(eta, |n . wo|) B (eq. 14).
std::vector<Rgb> outgoing_radiance(const SurfelCloud& cloud, const Material& material,
                                   const std::vector<Rgb>& B, const Eigen::Vector3d& view_direction);
// The same seen from the point `eye` (a perspective camera): wo from each surfel to the eye.
std::vector<Rgb> outgoing_radiance_to_eye(const SurfelCloud& cloud, const Material& material,
                                          const std::vector<Rgb>& B, const Eigen::Vector3d& eye);

// `cloud` validated, `B` one per surfel. Throws std::invalid_argument for a bad camera.
LinearImage render_view(const SurfelCloud& cloud, const Material& material,
                        const std::vector<Rgb>& B, const OrthoCamera& camera);

}  // namespace sss
