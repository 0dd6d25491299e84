#include "source_tree.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sss {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Patches split near a receiver: into pieces no larger than max(z_r / 2, distance / 8),
// at most this many (a patch of one piece is summed by its second-order expansion).
constexpr int kMaxPieces = 4096;
constexpr double kSplitDistanceRatio = 8.0;
// Deeper nodes stay leaves; bounds the traversal stack.
constexpr int kMaxDepth = 200;

double quad_form(const std::array<double, 6>& m, const Eigen::Vector3d& u) {
  return m[0] * u.x() * u.x() + m[3] * u.y() * u.y() + m[5] * u.z() * u.z() +
         2.0 * (m[1] * u.x() * u.y() + m[2] * u.x() * u.z() + m[4] * u.y() * u.z());
}

// Sum over a cluster of W g(|y - x|) by a second-order Taylor expansion about the centroid y0:
// W g(D) + 1/2 [g''(D) u'Mu + g'(D)/D (tr M - u'Mu)], u = (y0 - x) / D.
double expanded_term(double z, double s_tr, const Eigen::Vector3d& y0, const Eigen::Vector3d& x,
                     double weight, const std::array<double, 6>& second) {
  const Eigen::Vector3d offset = y0 - x;
  const double D = offset.norm();
  const Eigen::Vector3d u = offset / D;
  const DipoleTerm g = dipole_term(z, s_tr, D);
  const double radial = quad_form(second, u);
  const double trace = second[0] + second[3] + second[5];
  return weight * g.value + 0.5 * (g.d2 * radial + g.d1 / D * (trace - radial));
}

}  // namespace

SourceTree::SourceTree(const PointSources& sources, const Dipole& dipole,
                       const SourceTreeSettings& settings)
    : dipole_(dipole), settings_(settings) {
  if (!(settings.theta >= 0.0 && settings.theta < 1.0) || settings.leaf_size < 1 ||
      !(settings.kernel_tolerance > 0.0 && settings.kernel_tolerance < 1.0))
    throw std::invalid_argument(
        "[sss::SourceTree] theta must be in [0, 1), leaf_size >= 1, kernel_tolerance in (0, 1)");
  const std::size_t count = sources.size();
  if (sources.normal.size() != count || sources.power.size() != count ||
      sources.edge_u.size() != count || sources.edge_v.size() != count)
    throw std::invalid_argument("[sss::SourceTree] source arrays differ in size");
  cutoff_ = dipole.max_support_radius(settings.kernel_tolerance);
  split_spacing_ = 0.5 * dipole.min_z_r();
  const int n = static_cast<int>(count);
  // Copies that the build puts in tree order.
  position_ = sources.position;
  normal_ = sources.normal;
  power_ = sources.power;
  edge_u_ = sources.edge_u;
  edge_v_ = sources.edge_v;
  if (n > 0) {
    nodes_.reserve(2 * static_cast<std::size_t>(n) / std::max(1, settings.leaf_size) + 2);
    build(0, n, 0);
  }
}

int SourceTree::build(int first, int last, int depth) {
  Node node;
  node.first = first;
  node.last = last;
  node.lo = node.hi = position_[first];
  for (int k = first; k < last; ++k) {
    node.lo = node.lo.cwiseMin(position_[k]);
    node.hi = node.hi.cwiseMax(position_[k]);
  }
  for (int c = 0; c < 3; ++c) {
    const DipoleChannel& ch = dipole_.channel[c];
    for (int k = first; k < last; ++k) node.weight[c] += power_[k][c];
    for (int p = 0; p < 2; ++p) {
      // Real source z_r below, virtual source z_v above the surface (eq. 12, 13).
      const double offset = p == 0 ? -ch.z_r : ch.z_v;
      Pole& pole = node.pole[c][p];
      auto source = [&](int k) -> Eigen::Vector3d { return position_[k] + offset * normal_[k]; };
      if (node.weight[c] > 0.0) {
        for (int k = first; k < last; ++k) pole.centroid += power_[k][c] * source(k);
        pole.centroid /= node.weight[c];
      } else {
        pole.centroid = source(first);
      }
      for (int k = first; k < last; ++k) {
        const Eigen::Vector3d d = source(k) - pole.centroid;
        const double w = power_[k][c];
        pole.second[0] += w * d.x() * d.x();
        pole.second[1] += w * d.x() * d.y();
        pole.second[2] += w * d.x() * d.z();
        pole.second[3] += w * d.y() * d.y();
        pole.second[4] += w * d.y() * d.z();
        pole.second[5] += w * d.z() * d.z();
        pole.radius = std::max(pole.radius, d.norm());
      }
    }
  }
  const int index = static_cast<int>(nodes_.size());
  nodes_.push_back(node);
  // Split the box's longest side near its middle (not at a median: a median depends on the
  // order of nearly equal coordinates, which rounding can flip, so a shifted or rescaled
  // scene would get another tree and differ by the expansion's error). The plane sits a
  // little off the middle, where symmetric shapes and regular texel rows put no samples.
  int axis;
  const double extent = (node.hi - node.lo).maxCoeff(&axis);
  if (last - first > settings_.leaf_size && extent > 0.0 && depth < kMaxDepth) {
    const double middle = node.lo[axis] + 0.5137 * extent;
    std::vector<int> order;
    order.reserve(last - first);
    for (int k = first; k < last; ++k)
      if (position_[k][axis] < middle) order.push_back(k);
    const int mid = first + static_cast<int>(order.size());
    for (int k = first; k < last; ++k)
      if (!(position_[k][axis] < middle)) order.push_back(k);
    auto permute = [&](auto& values) {
      std::vector<std::decay_t<decltype(values[0])>> part(last - first);
      for (int k = 0; k < last - first; ++k) part[k] = values[order[k]];
      std::copy(part.begin(), part.end(), values.begin() + first);
    };
    permute(position_);
    permute(normal_);
    permute(power_);
    permute(edge_u_);
    permute(edge_v_);
    const int left = build(first, mid, depth + 1);
    const int right = build(mid, last, depth + 1);
    nodes_[index].left = left;
    nodes_[index].right = right;
  }
  return index;
}

bool SourceTree::well_separated(const Node& node, const Eigen::Vector3d& x) const {
  // The expansion also needs the receiver beyond the clamp of Rd_from_distances (z_v >= z_r).
  for (int c = 0; c < 3; ++c) {
    for (const Pole& pole : node.pole[c]) {
      const double distance = (pole.centroid - x).norm();
      if (!(pole.radius < settings_.theta * distance) || distance <= 2.0 * dipole_.channel[c].z_v)
        return false;
    }
  }
  return true;
}

void SourceTree::add_node(const Node& node, const Eigen::Vector3d& x, Rgb& sum) const {
  for (int c = 0; c < 3; ++c) {
    if (node.weight[c] <= 0.0) continue;
    const DipoleChannel& ch = dipole_.channel[c];
    const Pole& real = node.pole[c][0];
    const Pole& virt = node.pole[c][1];
    sum[c] += ch.alpha_prime / (4.0 * kPi) *
              (expanded_term(ch.z_r, ch.s_tr, real.centroid, x, node.weight[c], real.second) +
               expanded_term(ch.z_v, ch.s_tr, virt.centroid, x, node.weight[c], virt.second));
  }
}

void SourceTree::add_sample(int k, const Eigen::Vector3d& x, Rgb& sum) const {
  const Eigen::Vector3d& p = position_[k];
  const Eigen::Vector3d& n = normal_[k];
  const double distance = (p - x).norm();
  const double piece = std::max(split_spacing_, distance / kSplitDistanceRatio);
  const double radius = edge_u_[k].norm();  // the patch is a disc of this radius
  // A small disc far from both poles' planar minimum distances (where Rd_from_distances
  // clamps) is summed whole about its centre: second moment radius^2 / 4 along each tangent.
  bool whole = !(radius > 0.5 * piece) && !(radius > 0.5 * distance);
  for (int c = 0; c < 3 && whole; ++c) {
    const DipoleChannel& ch = dipole_.channel[c];
    whole = (p - ch.z_r * n - x).norm() > ch.z_r + radius &&
            (p + ch.z_v * n - x).norm() > ch.z_v + radius;
  }
  if (whole) {
    const double v = 0.25 * radius * radius;
    const std::array<double, 6> second{v * (1 - n.x() * n.x()), -v * n.x() * n.y(),
                                       -v * n.x() * n.z(),      v * (1 - n.y() * n.y()),
                                       -v * n.y() * n.z(),      v * (1 - n.z() * n.z())};
    for (int c = 0; c < 3; ++c) {
      const DipoleChannel& ch = dipole_.channel[c];
      sum[c] += power_[k][c] * ch.alpha_prime / (4.0 * kPi) *
                (expanded_term(ch.z_r, ch.s_tr, p - ch.z_r * n, x, 1.0, second) +
                 expanded_term(ch.z_v, ch.s_tr, p + ch.z_v * n, x, 1.0, second));
    }
    return;
  }
  // Equal-area rings about `piece` wide, each with points `piece` apart at even angles: a
  // rule whose first moment vanishes and whose second is the disc's. Points nearer to x than
  // to p are not the patch's (source_tree.h): the others share its power.
  const Eigen::Vector3d u = edge_u_[k] / radius, v = edge_v_[k] / radius;
  const int rings = std::max(1, static_cast<int>(std::ceil(radius / piece)));
  int points = 0;
  Rgb patch{0.0, 0.0, 0.0};
  double kept = 0.0;
  bool clipped = false;
  for (int r = 0; r < rings && points < kMaxPieces; ++r) {
    const double rho = radius * std::sqrt((r + 0.5) / rings);
    const int m = std::max(3, static_cast<int>(std::ceil(2.0 * kPi * rho / piece)));
    const double share = 1.0 / (static_cast<double>(rings) * m);
    for (int j = 0; j < m; ++j, ++points) {
      const double angle = 2.0 * kPi * (j + 0.5 * (r % 2)) / m;
      const Eigen::Vector3d q = p + rho * (std::cos(angle) * u + std::sin(angle) * v);
      if ((q - x).norm() < rho) {
        clipped = true;
        continue;
      }
      kept += share;
      for (int c = 0; c < 3; ++c) {
        const DipoleChannel& ch = dipole_.channel[c];
        const double d_r = (q - ch.z_r * n - x).norm();
        const double d_v = (q + ch.z_v * n - x).norm();
        patch[c] += share * power_[k][c] * ch.Rd_from_distances(d_r, d_v);
      }
    }
  }
  for (int c = 0; c < 3; ++c) sum[c] += clipped && kept > 0.0 ? patch[c] / kept : patch[c];
}

Rgb SourceTree::B(const Eigen::Vector3d& x, double beyond) const {
  Rgb sum{0.0, 0.0, 0.0};
  if (nodes_.empty()) return sum;
  int stack[kMaxDepth + 2];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    const Eigen::Vector3d outside = (node.lo - x).cwiseMax(x - node.hi).cwiseMax(0.0);
    const double near_gap = outside.norm();
    if (near_gap > cutoff_) continue;
    const double far_gap = (node.hi - x).cwiseAbs().cwiseMax((node.lo - x).cwiseAbs()).norm();
    if (far_gap < beyond) continue;  // every source of the node is nearer than `beyond`
    if (near_gap >= beyond && well_separated(node, x)) {
      add_node(node, x, sum);
    } else if (node.left < 0) {
      for (int k = node.first; k < node.last; ++k)
        if (!((position_[k] - x).norm() < beyond)) add_sample(k, x, sum);
    } else {
      stack[top++] = node.left;
      stack[top++] = node.right;
    }
  }
  for (double& v : sum) v /= kPi;
  return sum;
}

}  // namespace sss
