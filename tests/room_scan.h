// Test support for terrestrial scans: a 10 x 6 x 3 m room (floor at z = 0) scanned from one
// station, so its density falls with the square of range and with incidence.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace sss::test {

constexpr double kRoomStation[3] = {2.0, 2.0, 1.5};  // m

// The nearest hit among the room's six faces of each ray from the station, stepping `step`
// radians in elevation and, along each ring, in azimuth; range noise of standard deviation
// `noise` m drawn with `seed`.
std::vector<Eigen::Vector3d> room_scan(double step, double noise, unsigned seed);

}  // namespace sss::test
