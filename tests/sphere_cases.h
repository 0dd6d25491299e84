// Test support for curved surfaces: the Fibonacci sphere's local closed form, samples of its
// points, and B of one sampling carried to the points of another.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "light_map.h"
#include "material.h"
#include "surfel_cloud.h"

namespace sss::test {

// `count` surfels (fewer if fewer qualify) whose normal has a cosine above min_cos with
// `towards` (all when min_cos <= -1), drawn with `seed`, sorted.
std::vector<std::size_t> sample_of(const SurfelCloud& cloud, std::size_t count, unsigned seed,
                                   const Eigen::Vector3d& towards = Eigen::Vector3d::Zero(),
                                   double min_cos = -2.0);

// `n` points drawn uniformly on the unit sphere with `seed`: a Poisson-like sampling without an
// edge (unit normals equal the points).
std::vector<Eigen::Vector3d> random_unit_sphere(std::size_t n, unsigned seed);

// B on a surface far larger than the kernel, lit along `light`, at a point of normal n:
// Ft(theta) cos(theta) R_total / pi (exact to l_d / R).
Rgb local_closed_form(const Material& material, const Eigen::Vector3d& n,
                      const Eigen::Vector3d& light);

// The sampling-invariance case: a 30 mm sphere sampled as the Stanford bunny is (1.26 mm) and
// about three times finer (0.4 mm) on Fibonacci lattices, lit from (0.3, 0.4, 1), with 800 of
// the coarse points to compare at and their 6 nearest fine points.
struct TwoSamplings {
  SurfelCloud coarse, fine;
  std::vector<Light> light;
  std::vector<std::size_t> points;
  std::vector<std::vector<std::size_t>> neighbours;
};
TwoSamplings thirty_millimetre_spheres();

// The k nearest surfels of `fine` to each of coarse's `points`.
std::vector<std::vector<std::size_t>> nearest_of(const SurfelCloud& fine, const SurfelCloud& coarse,
                                                 const std::vector<std::size_t>& points, int k);

// B of `fine` at each of coarse's `points` (on the same surface), from a linear fit in the
// tangent plane over the 6 nearest fine surfels (`neighbours`, from nearest_of), so that the
// comparison is at the same place: B of a translucent sphere changes by several per cent over
// the 0.2 mm to the nearest fine point.
std::vector<Rgb> fitted_at(const SurfelCloud& coarse, const std::vector<std::size_t>& points,
                           const SurfelCloud& fine, const std::vector<Rgb>& fine_B,
                           const std::vector<std::vector<std::size_t>>& neighbours);

// The fine surfels that fitted_at reads, sorted and unique.
std::vector<std::size_t> fitted_sources(const std::vector<std::vector<std::size_t>>& neighbours);

}  // namespace sss::test
