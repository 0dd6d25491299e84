#include "dipole.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "fresnel.h"

namespace sss {
namespace {
constexpr double kPi = 3.14159265358979323846;
}

DipoleChannel::DipoleChannel(double sigma_a, double sigma_s_prime, double eta) {
  sigma_t_prime = sigma_a + sigma_s_prime;
  alpha_prime = sigma_s_prime / sigma_t_prime;
  s_tr = std::sqrt(3.0 * sigma_a * sigma_t_prime);
  z_r = 1.0 / sigma_t_prime;
  const double D = 1.0 / (3.0 * sigma_t_prime);  // eq. 8
  const double Fdr = diffuse_fresnel_reflectance(eta);
  A = (1.0 + Fdr) / (1.0 - Fdr);
  z_v = z_r + 4.0 * A * D;
}

DipoleTerm dipole_term(double z, double s, double d) {
  const double sd = s * d;
  const double e = std::exp(-sd);
  const double d2 = d * d;
  const double d3 = d2 * d;
  DipoleTerm t;
  t.value = z * (1.0 + sd) * e / d3;
  t.d1 = -z * e * (3.0 + 3.0 * sd + sd * sd) / (d3 * d);
  t.d2 = z * e * (12.0 + 12.0 * sd + 5.0 * sd * sd + sd * sd * sd) / (d3 * d2);
  return t;
}

double DipoleChannel::Rd_from_distances(double d_r, double d_v) const {
  d_r = std::max(d_r, z_r);
  d_v = std::max(d_v, z_v);
  const double real = z_r * (1.0 + s_tr * d_r) * std::exp(-s_tr * d_r) / (d_r * d_r * d_r);
  const double virt = z_v * (1.0 + s_tr * d_v) * std::exp(-s_tr * d_v) / (d_v * d_v * d_v);
  return alpha_prime / (4.0 * kPi) * (real + virt);
}

double DipoleChannel::Rd(double r) const {
  return Rd_from_distances(std::sqrt(r * r + z_r * z_r), std::sqrt(r * r + z_v * z_v));
}

double DipoleChannel::total_diffuse_reflectance() const {
  return 0.5 * alpha_prime * (std::exp(-s_tr * z_r) + std::exp(-s_tr * z_v));
}

double DipoleChannel::tail_reflectance(double rho) const {
  const double d_r = std::sqrt(rho * rho + z_r * z_r);
  const double d_v = std::sqrt(rho * rho + z_v * z_v);
  return 0.5 * alpha_prime *
         (z_r * std::exp(-s_tr * d_r) / d_r + z_v * std::exp(-s_tr * d_v) / d_v);
}

double DipoleChannel::disc_reflectance(double rho) const {
  return total_diffuse_reflectance() - tail_reflectance(rho);
}

double DipoleChannel::support_radius(double fraction) const {
  const double total = total_diffuse_reflectance();
  if (!(total > 0.0) || fraction >= 1.0) return 0.0;
  fraction = std::max(fraction, 1e-15);
  auto too_much = [&](double rho) { return tail_reflectance(rho) > fraction * total; };
  double lo = 0.0, hi = z_v;
  while (too_much(hi)) {
    lo = hi;
    hi *= 2.0;
    if (!std::isfinite(hi)) return std::numeric_limits<double>::infinity();
  }
  for (int i = 0; i < 200 && hi - lo > 1e-12 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (too_much(mid) ? lo : hi) = mid;
  }
  return hi;
}

double DipoleChannel::diffusion_length() const {
  return s_tr > 0.0 ? 1.0 / s_tr : std::numeric_limits<double>::infinity();
}

Dipole::Dipole(const Material& material) {
  material.validate();
  for (int c = 0; c < 3; ++c)
    channel[c] = DipoleChannel(material.sigma_a[c], material.sigma_s_prime[c], material.eta[c]);
}

double Dipole::min_z_r() const {
  return std::min({channel[0].z_r, channel[1].z_r, channel[2].z_r});
}

double Dipole::max_support_radius(double fraction) const {
  return std::max({channel[0].support_radius(fraction), channel[1].support_radius(fraction),
                   channel[2].support_radius(fraction)});
}

}  // namespace sss
