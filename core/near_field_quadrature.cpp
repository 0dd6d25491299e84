#include "near_field_quadrature.h"

#include "local_surface.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace sss {
namespace {

constexpr double kPi = 3.14159265358979323846;

// 8-point Gauss-Legendre nodes and weights on [-1, 1].
constexpr double kGaussX[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290,
                               -0.1834346424956498, 0.1834346424956498,  0.5255324099163290,
                               0.7966664774136267,  0.9602898564975363};
constexpr double kGaussW[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873,
                               0.3626837833783620, 0.3626837833783620, 0.3137066458778873,
                               0.2223810344533745, 0.1012285362903763};

// Integral over [a, b] of the kept part of Rd(r) 2 pi r dr, composite Gauss-Legendre.
double windowed_integral(const DipoleChannel& ch, const KernelWindow& window, double a, double b) {
  if (!(b > a)) return 0.0;
  constexpr int kPieces = 16;
  const double step = (b - a) / kPieces;
  double sum = 0.0;
  for (int p = 0; p < kPieces; ++p) {
    const double mid = a + (p + 0.5) * step;
    for (int g = 0; g < 8; ++g) {
      const double r = mid + 0.5 * step * kGaussX[g];
      sum += kGaussW[g] * 0.5 * step * window.weight(r) * ch.Rd(r) * 2.0 * kPi * r;
    }
  }
  return sum;
}

}  // namespace

double NearFieldQuadrature::kept_integral(const DipoleChannel& channel, const KernelWindow& window,
                                          double rho) {
  if (window.part == KernelWindow::Part::All) return channel.disc_reflectance(rho);
  if (window.part == KernelWindow::Part::Far)
    throw std::invalid_argument("[sss::NearFieldQuadrature] the near field keeps the near part");
  if (rho <= window.r0) return channel.disc_reflectance(rho);
  return channel.disc_reflectance(window.r0) +
         windowed_integral(channel, window, window.r0, std::min(rho, window.r1));
}

NearFieldQuadrature::NearFieldQuadrature(const Dipole& dipole, const KernelWindow& window,
                                         double reach, const QuadratureSettings& settings)
    : reach_(reach) {
  if (settings.rings < 1 || settings.min_nodes < 1 || settings.max_nodes < settings.min_nodes ||
      settings.radial < 1 || !std::isfinite(reach) || !(reach > 0.0)) {
    std::ostringstream msg;
    msg << "[sss::NearFieldQuadrature] rings = " << settings.rings << ", nodes per ring "
        << settings.min_nodes << " to " << settings.max_nodes << ", radial shares "
        << settings.radial << " and reach = " << reach
        << " mm must be at least 1, 1 <= min <= max, at least 1 and finite > 0";
    throw std::invalid_argument(msg.str());
  }
  if (window.part == KernelWindow::Part::Near) reach_ = std::min(reach_, window.r1);
  Rgb total{};
  for (int c = 0; c < 3; ++c) total[c] = kept_integral(dipole.channel[c], window, reach_);
  // The mixture of the channels' normalised integrals: rings hold equal shares of it.
  auto mixture = [&](double rho) {
    double f = 0.0;
    int channels = 0;
    for (int c = 0; c < 3; ++c) {
      if (!(total[c] > 0.0)) continue;
      f += kept_integral(dipole.channel[c], window, rho) / total[c];
      ++channels;
    }
    return channels > 0 ? f / channels : rho / reach_;
  };
  auto quantile = [&](double q) {
    double lo = 0.0, hi = reach_;
    for (int i = 0; i < 100 && hi - lo > 1e-12 * reach_; ++i) {
      const double mid = 0.5 * (lo + hi);
      (mixture(mid) < q ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  };
  const int n = settings.rings;
  std::vector<double> edge(n + 1);
  edge[0] = 0.0;
  edge[n] = reach_;
  for (int k = 1; k < n; ++k) edge[k] = quantile(static_cast<double>(k) / n);
  Rgb below{};
  for (int k = 0; k < n; ++k) {
    NearFieldRing ring;
    if (k > 0) {
      ring.radius = quantile((k + 0.5) / n);
      const double width = std::max(edge[k + 1] - edge[k], 1e-12 * reach_);
      ring.nodes = std::clamp(static_cast<int>(std::lround(2.0 * kPi * ring.radius / width)),
                              settings.min_nodes, settings.max_nodes);
      for (int m = 0; m < settings.radial; ++m)
        ring.radii.push_back(quantile((k + (m + 0.5) / settings.radial) / n));
    } else {
      ring.radii = {0.0};
    }
    for (int c = 0; c < 3; ++c) {
      const double upto = kept_integral(dipole.channel[c], window, edge[k + 1]);
      ring.node_weight[c] = (upto - below[c]) / ring.nodes;
      below[c] = upto;
    }
    rings_.push_back(ring);
  }
}

Rgb NearFieldQuadrature::bend(const Dipole& dipole, double rho, double kappa) {
  const Eigen::Vector3d n = Eigen::Vector3d::UnitZ();
  const SurfacePoint y = on_local_surface(Eigen::Vector3d::Zero(), n, kappa,
                                          Eigen::Vector3d(rho, 0.0, 0.0));
  Rgb ratio;
  for (int c = 0; c < 3; ++c) {
    const DipoleChannel& ch = dipole.channel[c];
    const double planar = ch.Rd(rho);
    ratio[c] = planar > 0.0 ? ch.Rd_from_distances((y.position - ch.z_r * y.normal).norm(),
                                                   (y.position + ch.z_v * y.normal).norm()) /
                                  planar
                            : 1.0;
  }
  return ratio;
}

int NearFieldQuadrature::node_count() const {
  int count = 0;
  for (const NearFieldRing& r : rings_) count += r.nodes;
  return count;
}

int NearFieldQuadrature::point_count() const {
  int count = 0;
  for (const NearFieldRing& r : rings_) count += r.nodes * static_cast<int>(r.radii.size());
  return count;
}

Rgb NearFieldQuadrature::total_weight() const {
  Rgb sum{};
  for (const NearFieldRing& r : rings_)
    for (int c = 0; c < 3; ++c) sum[c] += r.nodes * r.node_weight[c];
  return sum;
}

}  // namespace sss
