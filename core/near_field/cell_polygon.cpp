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
constexpr double kGauss2 = 0.5773502691896258;
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

namespace {

constexpr double kNarrowEdge = 0.2;   // radians: an edge seen under less takes 2 points
constexpr double kEdgePiece = 0.5;    // radians: wider edges take 8 points per piece this wide

// Adds Integral f(rho) d theta along the edge a -> b, the receiver at the origin (one edge of
// Green's theorem in polar coordinates), integrated in the angle phi from the foot of the
// perpendicular on the edge's line (rho = h / cos phi): a constant f integrates exactly, so
// the far edges of a cell that does not hold the origin cancel its near edges exactly, and a
// kernel peaked at the origin stays smooth along an edge that passes close to it.
// f(rho, Rgb&) writes the three channels.
template <class F>
void add_edge(const Eigen::Vector2d& a, const Eigen::Vector2d& b, F&& f, Rgb& sum) {
  const double cross = a.x() * b.y() - a.y() * b.x();
  const Eigen::Vector2d e = b - a;
  const double length = e.norm();
  if (cross == 0.0 || !(length > 0.0)) return;
  const Eigen::Vector2d along = e / length;
  const double h = std::fabs(cross) / length;  // the edge's line from the origin
  const double phi_a = std::atan2(a.dot(along), h), phi_b = std::atan2(b.dot(along), h);
  const double sign = cross > 0.0 ? 1.0 : -1.0;  // d theta = sign d phi
  const double span = phi_b - phi_a;
  const bool narrow = span < kNarrowEdge;
  const int pieces = narrow ? 1 : static_cast<int>(std::ceil(span / kEdgePiece));
  const double piece = span / pieces;
  Rgb value;
  for (int k = 0; k < pieces; ++k) {
    const double start = phi_a + k * piece;
    for (int g = 0; g < (narrow ? 2 : 8); ++g) {
      const double t = narrow ? 0.5 * (1.0 + (g ? kGauss2 : -kGauss2)) : 0.5 * (kGaussX[g] + 1.0);
      const double weight = narrow ? 0.5 : 0.5 * kGaussW[g];
      const double phi = start + t * piece;
      f(h / std::cos(phi), value);
      for (int c = 0; c < 3; ++c) sum[c] += sign * weight * piece * value[c];
    }
  }
}

// The centroid of a polygon of nonzero area.
Eigen::Vector2d centroid_of(const Polygon& polygon) {
  double twice = 0.0;
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[(i + 1) % polygon.size()];
    const double cross = a.x() * b.y() - a.y() * b.x();
    twice += cross;
    centroid += cross * (a + b);
  }
  return twice != 0.0 ? Eigen::Vector2d(centroid / (3.0 * twice)) : centroid;
}

// Where the contour sum of a channel comes out negative (rounding in a cell far from the
// receiver, whose edges cancel), the kernel at the cell's centroid times its area: a positive
// kernel over a positive area.
template <class K>
void positive_or_point_rule(const Polygon& polygon, K&& kernel_at, Rgb& sum) {
  if (sum[0] >= 0.0 && sum[1] >= 0.0 && sum[2] >= 0.0) return;
  const double area = std::fabs(signed_area(polygon));
  Rgb k;
  kernel_at(centroid_of(polygon).norm(), k);
  for (int c = 0; c < 3; ++c)
    if (!(sum[c] >= 0.0)) sum[c] = area * k[c];
}

}  // namespace

double signed_area(const Polygon& polygon) {
  double twice = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[(i + 1) % polygon.size()];
    twice += a.x() * b.y() - a.y() * b.x();
  }
  return 0.5 * twice;
}

Rgb kernel_over(const Polygon& polygon, const RadialKernel& kernel, double kappa) {
  Rgb sum{0.0, 0.0, 0.0};
  const auto G = [&](double rho, Rgb& g) { g = kernel.G(rho, kappa); };
  for (std::size_t i = 0; i < polygon.size(); ++i)
    add_edge(polygon[i], polygon[(i + 1) % polygon.size()], G, sum);
  positive_or_point_rule(polygon, [&](double rho, Rgb& k) { k = kernel.K(rho, kappa); }, sum);
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
  // The real pole z_r under the sources, the virtual one z_v above them.
  const auto G = [&](double rho, Rgb& g) {
    for (int c = 0; c < 3; ++c) {
      const DipoleChannel& ch = dipole.channel[c];
      g[c] = ch.alpha_prime / (4.0 * kPi) *
             (pole_integral(ch.z_r, ch.s_tr, height + ch.z_r, rho) +
              pole_integral(ch.z_v, ch.s_tr, height - ch.z_v, rho));
    }
  };
  for (std::size_t i = 0; i < polygon.size(); ++i)
    add_edge(polygon[i], polygon[(i + 1) % polygon.size()], G, sum);
  positive_or_point_rule(polygon, [&](double rho, Rgb& k) {
    for (int c = 0; c < 3; ++c) {
      const DipoleChannel& ch = dipole.channel[c];
      k[c] = ch.Rd_from_distances(std::hypot(rho, height + ch.z_r), std::hypot(rho, height - ch.z_v));
    }
  }, sum);
  return sum;
}

}  // namespace sss
