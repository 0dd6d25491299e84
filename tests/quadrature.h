// Test support: composite Gauss-Legendre quadrature, independent of the closed forms under test.
#pragma once

#include <cmath>
#include <vector>

namespace sss::test {

// Integral of f over [a, b] with `panels` panels of an n-point Gauss-Legendre rule.
template <typename F>
double integrate(const F& f, double a, double b, int panels = 400, int n = 10) {
  std::vector<double> x(n), w(n);
  for (int i = 0; i < n; ++i) {  // Newton iteration on the Legendre polynomial P_n
    double z = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1);
      const double dz = p1 / dp;
      z -= dz;
      if (std::fabs(dz) < 1e-16) break;
    }
    x[i] = z;
    w[i] = 2 / ((1 - z * z) * dp * dp);
  }
  double sum = 0;
  const double h = (b - a) / panels;
  for (int p = 0; p < panels; ++p) {
    const double mid = a + (p + 0.5) * h;
    for (int i = 0; i < n; ++i) sum += 0.5 * h * w[i] * f(mid + 0.5 * h * x[i]);
  }
  return sum;
}

// Integral of Rd(r) 2 pi r dr over [r0, r1] (r0 > 0), in the variable ln r so that both the
// peak near 0 and a 1/r^3 tail are resolved.
template <typename Channel>
double radial_integral(const Channel& ch, double r0, double r1) {
  return integrate([&](double u) {
    const double r = std::exp(u);
    return ch.Rd(r) * 2 * M_PI * r * r;
  }, std::log(r0), std::log(r1), 2000);
}

}  // namespace sss::test
