#include "cell_polygon.h"

#include <algorithm>
#include <cmath>

namespace sss {
namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr int kDiscSides = 24;
constexpr double kGaussX[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290,
                               -0.1834346424956498, 0.1834346424956498,  0.5255324099163290,
                               0.7966664774136267,  0.9602898564975363};
constexpr double kGaussW[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873,
                               0.3626837833783620, 0.3626837833783620, 0.3137066458778873,
                               0.2223810344533745, 0.1012285362903763};
}  // namespace

namespace {
// The unit circle's 24-gon of the circle's area: a regular n-gon of circumradius R has area
// n R^2 sin(2 pi / n) / 2.
struct UnitDisc {
  Eigen::Vector2d corner[kDiscSides];
  UnitDisc() {
    const double R = std::sqrt(2.0 * kPi / (kDiscSides * std::sin(2.0 * kPi / kDiscSides)));
    for (int k = 0; k < kDiscSides; ++k) {
      const double a = 2.0 * kPi * k / kDiscSides;
      corner[k] = R * Eigen::Vector2d(std::cos(a), std::sin(a));
    }
  }
};
const UnitDisc kUnitDisc;
}  // namespace

void disc_polygon(const Eigen::Vector2d& c, double r, Polygon& polygon) {
  polygon.resize(kDiscSides);
  for (int k = 0; k < kDiscSides; ++k) polygon[k] = c + r * kUnitDisc.corner[k];
}

void clip(Polygon& polygon, const Eigen::Vector2d& normal, double offset, Polygon& scratch) {
  if (polygon.empty()) return;
  Polygon& out = scratch;
  out.clear();
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[(i + 1) % polygon.size()];
    const double da = normal.dot(a) - offset, db = normal.dot(b) - offset;
    if (da <= 0.0) out.push_back(a);
    if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0)) out.push_back(a + (da / (da - db)) * (b - a));
  }
  polygon.swap(out);
  if (polygon.size() < 3) polygon.clear();
}

void clip_to_nearer(Polygon& polygon, const Eigen::Vector2d& own, const Eigen::Vector2d& other,
                    Polygon& scratch) {
  const Eigen::Vector2d n = other - own;
  clip(polygon, n, n.dot(0.5 * (own + other)), scratch);
}

Rgb kernel_over(const Polygon& polygon, const RadialKernel& kernel, double kappa) {
  constexpr double kGauss2 = 0.5773502691896258;
  Rgb sum{0.0, 0.0, 0.0};
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[(i + 1) % polygon.size()];
    const Eigen::Vector2d e = b - a;
    const double cross = a.x() * b.y() - a.y() * b.x();  // d theta = cross / |x|^2 dt
    if (cross == 0.0) continue;
    // An edge seen under a small angle needs 2 points, a wide one (the receiver's own cell) 8.
    const bool wide = std::fabs(cross) > 0.2 * a.norm() * b.norm() || a.dot(b) < 0.0;
    const int points = wide ? 8 : 2;
    for (int g = 0; g < points; ++g) {
      const double t = wide ? 0.5 * (kGaussX[g] + 1.0) : 0.5 * (1.0 + (g ? kGauss2 : -kGauss2));
      const double weight = wide ? kGaussW[g] : 1.0;
      const Eigen::Vector2d x = a + t * e;
      const double r2 = x.squaredNorm();
      if (!(r2 > 0.0)) continue;
      const Rgb G = kernel.G(std::sqrt(r2), kappa);
      const double w = 0.5 * weight * cross / r2;
      for (int c = 0; c < 3; ++c) sum[c] += w * G[c];
    }
  }
  return sum;
}

namespace {

// Integral_0^rho z (1 + s d) e^(-s d) / d^3 r dr, d = max(sqrt(r^2 + a^2), z): the term is
// constant where the clamp holds (r < sqrt(z^2 - a^2)), -z e^(-s d) / d beyond.
double pole_integral(double z, double s, double a, double rho) {
  const double flat = z * z > a * a ? std::sqrt(z * z - a * a) : 0.0;
  const double inner = std::min(rho, flat);
  double sum = (1.0 + s * z) * std::exp(-s * z) / (z * z) * 0.5 * inner * inner;
  if (rho > flat) {
    const double d0 = std::sqrt(flat * flat + a * a), d1 = std::sqrt(rho * rho + a * a);
    sum += z * (std::exp(-s * d0) / d0 - std::exp(-s * d1) / d1);
  }
  return sum;
}

}  // namespace

Rgb dipole_over(const Polygon& polygon, const Dipole& dipole, double height) {
  Rgb sum{0.0, 0.0, 0.0};
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[(i + 1) % polygon.size()];
    const double cross = a.x() * b.y() - a.y() * b.x();
    if (cross == 0.0) continue;
    for (int g = 0; g < 8; ++g) {
      const Eigen::Vector2d x = a + 0.5 * (kGaussX[g] + 1.0) * (b - a);
      const double r2 = x.squaredNorm();
      if (!(r2 > 0.0)) continue;
      const double rho = std::sqrt(r2);
      const double w = 0.5 * kGaussW[g] * cross / r2;
      for (int c = 0; c < 3; ++c) {
        const DipoleChannel& ch = dipole.channel[c];
        // The real pole z_r under the sources, the virtual one z_v above them.
        const double G = ch.alpha_prime / (4.0 * kPi) *
                         (pole_integral(ch.z_r, ch.s_tr, height + ch.z_r, rho) +
                          pole_integral(ch.z_v, ch.s_tr, height - ch.z_v, rho));
        sum[c] += w * G;
      }
    }
  }
  return sum;
}

}  // namespace sss
