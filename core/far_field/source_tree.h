// Hierarchical sum of eq. 16/17 over lit source elements: a binary tree over the sources,
// whose far nodes are summed by a second-order expansion of the dipole around each node's
// centroid (a treecode), and whose near leaves are evaluated source by source, splitting a
// source's patch when it is coarser than the kernel's local scale there. Receivers are
// surfels, whose cells no other surfel's cell reaches into (Voronoi cells, surfel_cells.h): a
// patch is taken only on its own point's side of the bisector with the receiver.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "dipole.h"
#include "material.h"

namespace sss {

// Source elements: patches of surface, each a disc around its point spanned by the
// orthogonal tangents edge_u and edge_v, whose length is the disc's radius, lit with power
// E dA per channel.
struct PointSources {
  std::vector<Eigen::Vector3d> position;  // local mm
  std::vector<Eigen::Vector3d> normal;    // unit, out of the material
  std::vector<Rgb> power;                 // E dA
  std::vector<Eigen::Vector3d> edge_u, edge_v;
  std::size_t size() const { return position.size(); }
};

struct SourceTreeSettings {
  // A node of radius S at distance D is summed as a whole when S < theta D; 0 sums every sample.
  double theta = 0.1;
  int leaf_size = 8;
  // Sources farther than the support radius of this fraction of the total reflectance are
  // skipped (the kernel's reach, DipoleChannel::support_radius).
  double kernel_tolerance = 1e-7;
};

class SourceTree {
 public:
  // Throws std::invalid_argument for a bad setting or arrays of different sizes.
  SourceTree(const PointSources& sources, const Dipole& dipole, const SourceTreeSettings& settings);

  // B(x) = 1/pi Sum E dA Rd(x_i, x) (eq. 17) over the sources whose point lies `beyond` mm or
  // farther from x (0: all of them).
  Rgb B(const Eigen::Vector3d& x, double beyond = 0.0) const;

  std::size_t node_count() const { return nodes_.size(); }
  double cutoff_radius() const { return cutoff_; }

 private:
  // One pole (real or virtual source) of one channel summed over a node's samples.
  struct Pole {
    Eigen::Vector3d centroid{Eigen::Vector3d::Zero()};
    std::array<double, 6> second{};  // xx xy xz yy yz zz about the centroid
    double radius = 0.0;             // farthest source from the centroid
  };
  struct Node {
    Eigen::Vector3d lo, hi;                 // box of the sample positions
    std::array<double, 3> weight{};         // Sum E dA per channel
    std::array<std::array<Pole, 2>, 3> pole;  // [channel][real, virtual]
    int first, last;                        // sample range [first, last)
    int left = -1, right = -1;
  };

  int build(int first, int last, int depth);
  bool well_separated(const Node& node, const Eigen::Vector3d& x) const;
  void add_node(const Node& node, const Eigen::Vector3d& x, Rgb& sum) const;
  void add_sample(int k, const Eigen::Vector3d& x, Rgb& sum) const;

  std::vector<Eigen::Vector3d> position_, normal_;
  std::vector<Rgb> power_;
  std::vector<Eigen::Vector3d> edge_u_, edge_v_;  // a source patch's tangents (its radius long)
  std::vector<Node> nodes_;
  Dipole dipole_;
  SourceTreeSettings settings_;
  double cutoff_ = 0.0;
  double split_spacing_ = 0.0;  // sub-sample spacing near a receiver: z_r / 2
};

}  // namespace sss
