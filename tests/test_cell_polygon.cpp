// The near field's integrals of the kernel over a cell (core/near_field/cell_polygon.h) against a
// direct sum over fine rings, where a cell's straight edge passes a few millimetres from the
// receiver (as a wall's cell does beside a roof's receiver in an airborne scan), and for a cell far
// away: positive, and within 0.2 % of the direct sum.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cell_polygon.h"
#include "dipole.h"
#include "radial_kernel.h"

namespace sss {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A square of side 2600 mm whose left edge lies at x = offset (the receiver at the origin is
// outside it for offset > 0, inside for offset < 0).
constexpr double kSide = 2600.0;
Polygon square_beside(double offset) {
  return {{offset, -0.5 * kSide}, {offset + kSide, -0.5 * kSide}, {offset + kSide, 0.5 * kSide},
          {offset, 0.5 * kSide}};
}

// Integral of k(rho) over square_beside(offset) within `radius` of the origin, by midpoints of
// fine rings: within the radius only the square's left edge crosses a ring (the test asserts
// it), so the ring's share inside is its arc beyond the chord x = offset, acos(offset / r) / pi.
template <class K>
Rgb direct(double offset, double radius, K&& k) {
  EXPECT_LT(radius, 0.5 * kSide - std::abs(offset)) << "another edge of the square within reach";
  const int rings = 200000;
  const double dr = radius / rings;
  Rgb sum{0, 0, 0};
  for (int i = 0; i < rings; ++i) {
    const double r = (i + 0.5) * dr;
    const double share = std::acos(std::clamp(offset / r, -1.0, 1.0)) / kPi;
    if (share == 0.0) continue;
    const Rgb v = k(r);
    for (int c = 0; c < 3; ++c) sum[c] += v[c] * 2.0 * kPi * r * dr * share;
  }
  return sum;
}

void expect_close(const char* what, const Rgb& got, const Rgb& want) {
  std::printf("[ cell polygon ] %s: %.6g %.6g %.6g, direct sum %.6g %.6g %.6g\n", what, got[0],
              got[1], got[2], want[0], want[1], want[2]);
  for (int c = 0; c < 3; ++c) {
    EXPECT_GE(got[c], 0.0) << what;
    EXPECT_NEAR(got[c], want[c], 2e-3 * want[c] + 1e-12) << what << " channel " << c;
  }
}

TEST(CellPolygon, AnEdgeNearTheReceiverIntegratesTheKernelExactly) {
  const Dipole skin(Material::preset("skin1", 1.3, 1000.0));
  const double support = skin.max_support_radius(kKernelSupportFraction);
  for (const double offset : {5.0, 0.5, -5.0}) {
    const Polygon cell = square_beside(offset);
    // Another surface's cell in its own plane, the receiver in that plane (height 0).
    const Rgb over_plane = dipole_over(cell, skin, 0.0);
    const Rgb want_plane = direct(offset, support, [&](double r) {
      Rgb k;
      for (int c = 0; c < 3; ++c)
        k[c] = skin.channel[c].Rd_from_distances(std::hypot(r, skin.channel[c].z_r),
                                                 std::hypot(r, skin.channel[c].z_v));
      return k;
    });
    char what[96];
    std::snprintf(what, sizeof what, "dipole_over, edge %+.1f mm from the receiver", offset);
    expect_close(what, over_plane, want_plane);
    // The receiver's own surface, curved: the radial kernel tabulated to its support, as the
    // near field's table takes it (near_field.cpp).
    const double kappa_limit = 1.0 / 1500.0;
    const RadialKernel kernel(skin, support, kappa_limit);
    for (const double kappa : {0.0, -kappa_limit, 0.5 * kappa_limit}) {
      const Rgb got = kernel_over(cell, kernel, kappa);
      const Rgb want = direct(offset, support, [&](double r) { return kernel.K(r, kappa); });
      std::snprintf(what, sizeof what, "kernel_over, edge %+.1f mm, kappa %.2g / mm", offset, kappa);
      expect_close(what, got, want);
    }
  }
}

TEST(CellPolygon, ACellFarFromTheReceiverWeighsNothingNegative) {
  const Dipole skin(Material::preset("skin1", 1.3, 1000.0));
  const RadialKernel kernel(skin, 3000.0, 1.0 / 1500.0);
  // A thin sliver 1 m away and a wide cell 1 m away, as tilted cells project.
  const Polygon sliver{{1000.0, 0.0}, {1400.0, 3.0}, {1000.0, 6.0}};
  const Polygon wide = square_beside(1000.0);
  for (const Polygon* p : {&sliver, &wide}) {
    const Rgb a = kernel_over(*p, kernel, 0.0), b = dipole_over(*p, skin, 0.0);
    for (int c = 0; c < 3; ++c) {
      EXPECT_GE(a[c], 0.0);
      EXPECT_LT(a[c], 1e-12);
      EXPECT_GE(b[c], 0.0);
      EXPECT_LT(b[c], 1e-12);
    }
  }
}

}  // namespace
}  // namespace sss
