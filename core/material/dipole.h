// Dipole diffusion profile Rd (Jensen et al. 2001; the paper's eq. 3-13), one colour channel.
// Lengths in mm, Rd in 1/mm^2.
#pragma once

#include <array>

#include "material.h"

namespace sss {

struct DipoleChannel {
  double sigma_t_prime = 0;  // eq. 4: sigma_a + sigma_s'
  double alpha_prime = 0;    // eq. 5: sigma_s' / sigma_t'
  double s_tr = 0;           // eq. 6: sqrt(3 sigma_a sigma_t'), effective transport coefficient
  double z_r = 0;            // eq. 7: depth of the real source, 1 / sigma_t'
  double z_v = 0;            // eq. 10: height of the virtual source, z_r + 4 A D
  double A = 0;              // eq. 9: (1 + Fdr) / (1 - Fdr)

  DipoleChannel() = default;
  DipoleChannel(double sigma_a, double sigma_s_prime, double eta);

  // Rd at planar distance r between entry and exit point (eq. 3).
  double Rd(double r) const;
  // Rd for a source at x_i with normal n_i and a receiver at x_o, given the distances
  // d_r = |x_i - z_r n_i - x_o| and d_v = |x_i + z_v n_i - x_o| (eq. 3, 12, 13).
  // The distances are clamped at their planar minima z_r and z_v: on a plane this changes
  // nothing, while on thin or curved parts a receiver lying z_r under another lit surface
  // would otherwise meet the real source's 1/d^3 singularity (its sum over a surface grows
  // as 1/d); so the kernel never exceeds Rd(0).
  double Rd_from_distances(double d_r, double d_v) const;
  // Integral of Rd 2 pi r dr over the whole plane: total diffuse reflectance (closed form).
  double total_diffuse_reflectance() const;
  // Integral of Rd 2 pi r dr over the disc r < rho (closed form).
  double disc_reflectance(double rho) const;
  // Integral of Rd 2 pi r dr over r >= rho (closed form, no cancellation for large rho).
  double tail_reflectance(double rho) const;
  // Smallest rho whose tail carries at most `fraction` of the total; finite also for
  // sigma_a = 0, where the tail falls off as 1/rho instead of exponentially.
  double support_radius(double fraction) const;
  // 1 / s_tr, the diffusion length (infinite when sigma_a = 0).
  double diffusion_length() const;
};

// One source term z (1 + s d) exp(-s d) / d^3 of eq. 3 and its first two derivatives in d,
// used by the far-field expansion of the source tree.
struct DipoleTerm {
  double value, d1, d2;
};
DipoleTerm dipole_term(double z, double s_tr, double d);

// Sources beyond a kernel's support radius at this fraction carry less than it of the kernel's
// integral: the step 2 GPU path skips them, and a distributed cloud's pieces exchange the
// surfels within this reach of each other.
constexpr double kKernelSupportFraction = 1e-7;

struct Dipole {
  std::array<DipoleChannel, 3> channel;
  explicit Dipole(const Material& material);
  // Smallest z_r and largest support over the channels, in mm.
  double min_z_r() const;
  double max_support_radius(double fraction) const;
};

}  // namespace sss
