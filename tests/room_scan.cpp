#include "room_scan.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace sss::test {

std::vector<Eigen::Vector3d> room_scan(double step, double noise, unsigned seed) {
  constexpr double kPi = 3.14159265358979323846;
  const Eigen::Vector3d station(kRoomStation[0], kRoomStation[1], kRoomStation[2]);
  const Eigen::Vector3d lo(0, 0, 0), hi(10, 6, 3);
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

}  // namespace sss::test
