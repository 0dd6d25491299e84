// The dipole kernel integrated radially on a receiver's local surface, for the exact integral of
// eq. 17 over a polygon (cell_polygon.h): with K(r) = Rd(r) bend(r, kappa),
//   G(rho) = Integral_0^rho K(r) r dr,   so that   Integral_P K dA = Contour_P G(rho) dtheta
// around any polygon P in the tangent plane (Green's theorem in polar coordinates, the
// receiver at the origin). The bend of a surface of mean curvature kappa is fitted as
// 1 + kappa b1(r) + kappa^2 b2(r) through its exact values at +-kappa_limit (bend()), so
// G = G0 + kappa G1 + kappa^2 G2, each tabulated finely in rho and read linearly.
#pragma once

#include <array>
#include <vector>

#include "dipole.h"
#include "material.h"

namespace sss {

class RadialKernel {
 public:
  RadialKernel() = default;
  // Tabulated on [0, rho_max] mm. Throws std::invalid_argument for a rho_max or kappa_limit
  // that is not finite and positive.
  RadialKernel(const Dipole& dipole, double rho_max, double kappa_limit);

  // G per channel at rho (clamped to the table) for curvature kappa (clamped to the limit).
  Rgb G(double rho, double kappa) const;
  // The kernel itself, Rd(rho) times the exact bend (not the fit), per channel: >= 0.
  Rgb K(double rho, double kappa) const;
  double rho_max() const { return rho_max_; }
  double kappa_limit() const { return kappa_limit_; }

  // How much a point at distance rho on a surface of mean curvature kappa (the osculating
  // paraboloid of local_surface.h) weighs against the same point on a plane: eq. 3 from the
  // point and normal there over eq. 3 at rho on a plane, per channel (1 at kappa = 0).
  static Rgb bend(const Dipole& dipole, double rho, double kappa);

 private:
  static Rgb bend(const std::array<DipoleChannel, 3>& channel, double rho, double kappa);

  std::array<DipoleChannel, 3> channel_{};
  double rho_max_ = 0.0, kappa_limit_ = 0.0, step_ = 0.0;
  std::vector<std::array<Rgb, 3>> table_;  // per sample: G0, G1, G2
};

}  // namespace sss
