// Surfels: oriented discs of one radius or one each, with an optional per-point albedo.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

#include "material.h"

namespace sss {

struct Bounds {
  Eigen::Vector3d min{Eigen::Vector3d::Constant(0)};
  Eigen::Vector3d max{Eigen::Vector3d::Constant(0)};
  bool empty = true;
  void extend(const Eigen::Vector3d& p);
  Eigen::Vector3d center() const { return 0.5 * (min + max); }
  Eigen::Vector3d extent() const { return max - min; }
  // The origin of a cloud's local frame (LocalFrame): the centre rounded to a power-of-two
  // step between 2^-13 and 2^-12 of the largest extent. Moving a cloud by a multiple of that
  // step (any whole number of units, for clouds under 8192 units across) moves the origin by
  // the same amount exactly, so its local coordinates stay the same bit for bit.
  Eigen::Vector3d frame_origin() const;
};

// What validation removed or changed; counts refer to the input points.
struct CloudReport {
  std::size_t input = 0;
  std::size_t kept = 0;
  std::size_t nonfinite_position = 0;
  std::size_t nonfinite_normal = 0;
  std::size_t zero_normal = 0;
  std::size_t renormalised = 0;
  std::size_t dropped() const { return input - kept; }
  std::string summary() const;
};

class SurfelCloud {
 public:
  std::vector<Eigen::Vector3d> positions;  // scene units
  std::vector<Eigen::Vector3d> normals;
  std::vector<Rgb> albedo;                 // empty, or one per point (each channel in [0, 1])
  double radius = 0.0;                     // the cells' radius, scene units (local_surfels.h)
  std::vector<double> radii;               // empty (radius), or each disc's in the views
  std::vector<std::size_t> input_index;    // input position of each kept point

  std::size_t size() const { return positions.size(); }
  bool empty() const { return positions.empty(); }
  double radius_of(std::size_t i) const { return radii.empty() ? radius : radii[i]; }

  // Drops points with a non-finite position or normal or a normal shorter than 1e-12,
  // normalises the rest, fills input_index. Throws std::invalid_argument (naming the value)
  // for mismatched array sizes, a non-finite or non-positive radius on a non-empty cloud,
  // or an albedo outside [0, 1].
  CloudReport validate();

  Bounds bounds() const;

  // Mean distance from a point to its nearest neighbour (FLANN k-d tree), scene units;
  // 0 for fewer than two distinct points.
  double mean_spacing() const;
};

// Scene units to the renderer's local millimetres: origin at the bounds centre (in double, so
// georeferenced coordinates near 1e6 keep their precision), scaled by mm per unit.
struct LocalFrame {
  Eigen::Vector3d origin{Eigen::Vector3d::Zero()};
  double mm_per_unit = 1.0;
  Eigen::Vector3d to_mm(const Eigen::Vector3d& p) const { return (p - origin) * mm_per_unit; }
};

}  // namespace sss
