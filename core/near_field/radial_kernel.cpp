#include "radial_kernel.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "local_surface.h"

namespace sss {
namespace {
constexpr int kSamples = 8192;
}

Rgb RadialKernel::bend(const Dipole& dipole, double rho, double kappa) {
  return bend(dipole.channel, rho, kappa);
}

Rgb RadialKernel::bend(const std::array<DipoleChannel, 3>& channel, double rho, double kappa) {
  const Eigen::Vector3d n = Eigen::Vector3d::UnitZ();
  const SurfacePoint y = on_local_surface(Eigen::Vector3d::Zero(), n, kappa,
                                          Eigen::Vector3d(rho, 0.0, 0.0));
  Rgb ratio;
  for (int c = 0; c < 3; ++c) {
    const DipoleChannel& ch = channel[c];
    const double planar = ch.Rd(rho);
    ratio[c] = planar > 0.0 ? ch.Rd_from_distances((y.position - ch.z_r * y.normal).norm(),
                                                   (y.position + ch.z_v * y.normal).norm()) /
                                  planar
                            : 1.0;
  }
  return ratio;
}

RadialKernel::RadialKernel(const Dipole& dipole, double rho_max, double kappa_limit)
    : channel_(dipole.channel), rho_max_(rho_max), kappa_limit_(kappa_limit) {
  if (!std::isfinite(rho_max) || !(rho_max > 0.0) || !std::isfinite(kappa_limit) ||
      !(kappa_limit > 0.0)) {
    std::ostringstream msg;
    msg << "[sss::RadialKernel] rho_max = " << rho_max << " mm and kappa_limit = " << kappa_limit
        << " / mm must be finite and > 0";
    throw std::invalid_argument(msg.str());
  }
  step_ = rho_max / kSamples;
  // The integrand's three parts at r: K0 = Rd r, K1 = K0 b1, K2 = K0 b2.
  auto parts = [&](double r) {
    std::array<Rgb, 3> k{};
    const Rgb up = bend(dipole, r, kappa_limit), down = bend(dipole, r, -kappa_limit);
    for (int c = 0; c < 3; ++c) {
      const double k0 = dipole.channel[c].Rd(r) * r;
      k[0][c] = k0;
      k[1][c] = k0 * (up[c] - down[c]) / (2.0 * kappa_limit);
      k[2][c] = k0 * (up[c] + down[c] - 2.0) / (2.0 * kappa_limit * kappa_limit);
    }
    return k;
  };
  // Simpson's rule on each step (its midpoint), accumulated.
  table_.assign(kSamples + 1, {});
  std::array<Rgb, 3> left = parts(0.0);
  for (int i = 0; i < kSamples; ++i) {
    const std::array<Rgb, 3> mid = parts((i + 0.5) * step_), right = parts((i + 1) * step_);
    for (int p = 0; p < 3; ++p)
      for (int c = 0; c < 3; ++c)
        table_[i + 1][p][c] =
            table_[i][p][c] + step_ / 6.0 * (left[p][c] + 4.0 * mid[p][c] + right[p][c]);
    left = right;
  }
}

Rgb RadialKernel::G(double rho, double kappa) const {
  const double t = std::clamp(rho / step_, 0.0, static_cast<double>(kSamples));
  const int i = std::min(static_cast<int>(t), kSamples - 1);
  const double f = t - i;
  const double k = std::clamp(kappa, -kappa_limit_, kappa_limit_);
  Rgb g;
  for (int c = 0; c < 3; ++c) {
    double v[3];
    for (int p = 0; p < 3; ++p) v[p] = (1.0 - f) * table_[i][p][c] + f * table_[i + 1][p][c];
    g[c] = v[0] + k * v[1] + k * k * v[2];
  }
  return g;
}

Rgb RadialKernel::K(double rho, double kappa) const {
  const Rgb b = bend(channel_, rho, std::clamp(kappa, -kappa_limit_, kappa_limit_));
  Rgb k;
  for (int c = 0; c < 3; ++c) k[c] = channel_[c].Rd(rho) * b[c];
  return k;
}

}  // namespace sss
