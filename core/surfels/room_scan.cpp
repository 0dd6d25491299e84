#include "room_scan.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace sss {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kCeilingCut = 0.01;  // m below the ceiling: its points and their noise go
}

std::vector<Eigen::Vector3d> room_scan(double step, double noise, unsigned seed) {
  const Eigen::Vector3d station(kRoomStation[0], kRoomStation[1], kRoomStation[2]);
  const Eigen::Vector3d lo(0, 0, 0), hi(kRoomSize[0], kRoomSize[1], kRoomSize[2]);
  std::mt19937 rng(seed);
  std::normal_distribution<double> range_noise(0.0, noise);
  std::vector<Eigen::Vector3d> points;
  for (double elevation = -0.5 * kPi + step; elevation < 0.5 * kPi; elevation += step)
    for (double azimuth = 0.0; azimuth < 2.0 * kPi; azimuth += step / std::cos(elevation)) {
      const Eigen::Vector3d ray(std::cos(elevation) * std::cos(azimuth),
                                std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
      double t = 1e9;
      for (int a = 0; a < 3; ++a)
        if (std::abs(ray[a]) > 1e-12)
          t = std::min(t, ((ray[a] > 0 ? hi[a] : lo[a]) - station[a]) / ray[a]);
      points.push_back(station + (t + range_noise(rng)) * ray);
    }
  return points;
}

std::vector<Eigen::Vector3d> open_room_scan(std::size_t count, double noise, unsigned seed) {
  const auto open = [&](double step) {
    std::vector<Eigen::Vector3d> points = room_scan(step, noise, seed);
    points.erase(std::remove_if(points.begin(), points.end(),
                                [](const Eigen::Vector3d& p) {
                                  return p.z() > kRoomSize[2] - kCeilingCut;
                                }),
                 points.end());
    return points;
  };
  // A step's rays cover the sphere's 4 pi at about step^2 each; one correction for the share
  // that the ceiling takes.
  const double target = static_cast<double>(std::max<std::size_t>(count, 1));
  double step = std::sqrt(4.0 * kPi / target);
  const std::size_t first = open(step).size();
  step *= std::sqrt(static_cast<double>(std::max<std::size_t>(first, 1)) / target);
  return open(step);
}

std::vector<Eigen::Vector3d> uniform_open_room(std::size_t count, double noise, unsigned seed) {
  const double X = kRoomSize[0], Y = kRoomSize[1], Z = kRoomSize[2];
  // Floor, walls at y = 0 and y = Y, walls at x = 0 and x = X: their areas.
  const double areas[5] = {X * Y, X * Z, X * Z, Y * Z, Y * Z};
  std::mt19937 rng(seed);
  std::discrete_distribution<int> face(std::begin(areas), std::end(areas));
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> off(0.0, noise);
  std::vector<Eigen::Vector3d> points;
  points.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const double a = u(rng), b = u(rng), h = noise > 0.0 ? off(rng) : 0.0;
    switch (face(rng)) {
      case 0: points.emplace_back(a * X, b * Y, h); break;
      case 1: points.emplace_back(a * X, h, b * Z); break;
      case 2: points.emplace_back(a * X, Y - h, b * Z); break;
      case 3: points.emplace_back(h, a * Y, b * Z); break;
      default: points.emplace_back(X - h, a * Y, b * Z); break;
    }
  }
  return points;
}

}  // namespace sss
