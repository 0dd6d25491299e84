// Synthetic terrestrial scans with known geometry: a 10 x 6 x 3 m room (floor at z = 0, units m)
// scanned from one station, so that its density falls with the square of range and with
// incidence as a terrestrial scanner's does; and the same faces sampled uniformly, the cloud a
// scan of that room would be without its density spread. For the tests and the benchmark.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

namespace sss {

constexpr double kRoomStation[3] = {2.0, 2.0, 1.5};  // m
constexpr double kRoomSize[3] = {10.0, 6.0, 3.0};    // m

// The nearest hit among the room's six faces of each ray from the station, stepping `step`
// radians in elevation and, along each ring, in azimuth; range noise of standard deviation
// `noise` m drawn with `seed`.
std::vector<Eigen::Vector3d> room_scan(double step, double noise, unsigned seed);

// The room open to the sky (its ceiling left out, so that a directional light reaches in) from
// the station, with the step that gives about `count` points (within a few per cent).
std::vector<Eigen::Vector3d> open_room_scan(std::size_t count, double noise, unsigned seed);

// `count` points uniform by area over the open room's floor and four walls, with normal noise
// of standard deviation `noise` m off each face, drawn with `seed`.
std::vector<Eigen::Vector3d> uniform_open_room(std::size_t count, double noise, unsigned seed);

}  // namespace sss
