#include "sphere_cases.h"

#include <flann/flann.hpp>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <random>

#include "dipole.h"
#include "fresnel.h"
#include "procedural_shapes.h"

namespace sss::test {

std::vector<std::size_t> sample_of(const SurfelCloud& cloud, std::size_t count, unsigned seed,
                                   const Eigen::Vector3d& towards, double min_cos) {
  std::vector<std::size_t> ids;
  for (std::size_t i = 0; i < cloud.size(); ++i)
    if (cloud.normals[i].dot(towards) > min_cos) ids.push_back(i);
  std::mt19937 rng(seed);
  std::shuffle(ids.begin(), ids.end(), rng);
  ids.resize(std::min(count, ids.size()));
  std::sort(ids.begin(), ids.end());
  return ids;
}

Rgb local_closed_form(const Material& material, const Eigen::Vector3d& n,
                      const Eigen::Vector3d& light) {
  const Dipole dipole(material);
  const double c = n.dot(light.normalized());
  Rgb e;
  for (int k = 0; k < 3; ++k)
    e[k] = fresnel_transmittance(material.eta[k], c) * c *
           dipole.channel[k].total_diffuse_reflectance() / M_PI;
  return e;
}

std::vector<std::vector<std::size_t>> nearest_of(const SurfelCloud& fine, const SurfelCloud& coarse,
                                                 const std::vector<std::size_t>& points, int k) {
  std::vector<double> data(3 * fine.size()), query(3 * points.size());
  for (std::size_t i = 0; i < fine.size(); ++i)
    for (int a = 0; a < 3; ++a) data[3 * i + a] = fine.positions[i][a];
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int a = 0; a < 3; ++a) query[3 * i + a] = coarse.positions[points[i]][a];
  flann::Matrix<double> d(data.data(), fine.size(), 3), q(query.data(), points.size(), 3);
  flann::Index<flann::L2<double>> index(d, flann::KDTreeSingleIndexParams(16));
  index.buildIndex();
  std::vector<std::vector<std::size_t>> ids;
  std::vector<std::vector<double>> dist2;
  index.knnSearch(q, ids, dist2, k, flann::SearchParams());
  return ids;
}

std::vector<Rgb> fitted_at(const SurfelCloud& coarse, const std::vector<std::size_t>& points,
                           const SurfelCloud& fine, const std::vector<Rgb>& fine_B,
                           const std::vector<std::vector<std::size_t>>& neighbours) {
  std::vector<Rgb> out;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Eigen::Vector3d& p = coarse.positions[points[k]];
    const Eigen::Vector3d n = coarse.normals[points[k]];
    const Eigen::Vector3d t1 = n.unitOrthogonal(), t2 = n.cross(t1);
    const int m = static_cast<int>(neighbours[k].size());
    Eigen::MatrixXd A(m, 3), Y(m, 3);
    for (int q = 0; q < m; ++q) {
      const std::size_t j = neighbours[k][q];
      const Eigen::Vector3d d = fine.positions[j] - p;
      A.row(q) << 1.0, d.dot(t1), d.dot(t2);
      for (int c = 0; c < 3; ++c) Y(q, c) = fine_B[j][c];
    }
    const Eigen::MatrixXd fit = A.colPivHouseholderQr().solve(Y);
    out.push_back({fit(0, 0), fit(0, 1), fit(0, 2)});
  }
  return out;
}

std::vector<std::size_t> fitted_sources(const std::vector<std::vector<std::size_t>>& neighbours) {
  std::vector<std::size_t> ids;
  for (const auto& row : neighbours) ids.insert(ids.end(), row.begin(), row.end());
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

TwoSamplings thirty_millimetre_spheres() {
  const double R = 30.0;
  auto count_for = [&](double h) { return static_cast<int>(4 * M_PI * R * R / (0.866 * h * h)); };
  TwoSamplings two;
  two.coarse = make_fibonacci_sphere(R, count_for(1.26));
  two.fine = make_fibonacci_sphere(R, count_for(0.4));
  two.light = {{Eigen::Vector3d(0.3, 0.4, 1.0), 1.0}};
  two.points = sample_of(two.coarse, 800, 3);
  two.neighbours = nearest_of(two.fine, two.coarse, two.points, 6);
  return two;
}

std::vector<Eigen::Vector3d> random_unit_sphere(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<Eigen::Vector3d> points(n);
  for (Eigen::Vector3d& x : points) x = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
  return points;
}

}  // namespace sss::test
