// Quadrature of the near part of eq. 17 on the receiver's local surface: rings around the
// receiver, each holding an equal share of the kernel's near-part integral (mixed over the
// three channels), with nodes spread evenly in angle, each node split into equal shares at
// several radii across its ring. A node's weight per channel is the exact integral of
// (1 - w(rho)) Rd(rho) 2 pi rho d rho over its ring, over the ring's node count, so the weights
// of a uniformly lit plane sum to the near part's closed form whatever the number of nodes or
// the surfel spacing.
#pragma once

#include <vector>

#include "dipole.h"
#include "kernel_window.h"
#include "material.h"

namespace sss {

struct NearFieldRing {
  double radius = 0.0;         // mm from the receiver: the ring's middle (0: the centre node)
  std::vector<double> radii;   // where a node's equal shares lie across the ring, mm
  int nodes = 1;               // spread evenly in angle
  Rgb node_weight{};           // per node and channel: its share of the near integral
};

struct QuadratureSettings {
  int rings = 8;        // including the centre node's disc
  int min_nodes = 4;    // per ring, outside the centre
  int max_nodes = 12;
  int radial = 2;       // shares per node across its ring (the centre node has one)
};

class NearFieldQuadrature {
 public:
  NearFieldQuadrature() = default;
  // The near part of the kernel as `window` (Near, or All up to `reach`) keeps it. Throws
  // std::invalid_argument for fewer than 1 ring, a node count below 1, or a reach that is not
  // finite and positive.
  NearFieldQuadrature(const Dipole& dipole, const KernelWindow& window, double reach,
                      const QuadratureSettings& settings);

  const std::vector<NearFieldRing>& rings() const { return rings_; }
  double reach() const { return reach_; }
  int node_count() const;   // nodes (angles) over all rings
  int point_count() const;  // nodes times their shares
  // Sum of every node's weight: Integral_0^reach (1 - w) Rd 2 pi rho d rho per channel.
  Rgb total_weight() const;

  // How much a node at distance rho on a surface of mean curvature kappa (the osculating
  // paraboloid of local_surface.h) weighs against the same node on a plane: eq. 3 from the
  // node's point and normal over eq. 3 at rho on a plane, per channel (1 at kappa = 0).
  static Rgb bend(const Dipole& dipole, double rho, double kappa);

  // Integral_0^rho of the kept part of Rd 2 pi r dr for one channel (closed form inside r0,
  // Gauss-Legendre over the window's rise).
  static double kept_integral(const DipoleChannel& channel, const KernelWindow& window,
                              double rho);

 private:
  std::vector<NearFieldRing> rings_;
  double reach_ = 0.0;
};

}  // namespace sss
