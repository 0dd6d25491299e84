#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>

#include "dipole.h"
#include "quadrature.h"

namespace sss {
namespace {

double plane_integral(const DipoleChannel& ch) {
  // [0, 1e-9 z_r] adds at most Rd(0) pi r^2; beyond 1e9 z_v the tail is below 1e-9 of the
  // total even without absorption (it falls as (z_r + z_v) / 2 r there).
  const double r0 = 1e-9 * ch.z_r;
  return ch.Rd(0) * M_PI * r0 * r0 + test::radial_integral(ch, r0, 1e9 * ch.z_v);
}

TEST(Dipole, PlaneIntegralEqualsClosedFormForAllMaterials) {
  for (const std::string& name : Material::preset_names()) {
    for (double eta : {1.0, 1.3, 1.5}) {
      const Dipole dipole(Material::preset(name, eta));
      for (int c = 0; c < 3; ++c) {
        const DipoleChannel& ch = dipole.channel[c];
        const double closed = ch.total_diffuse_reflectance();
        const double numeric = plane_integral(ch);
        EXPECT_NEAR(numeric / closed, 1.0, 1e-4) << name << " eta " << eta << " channel " << c;
      }
    }
  }
}

TEST(Dipole, TotalsMatchTheDesignNotes) {
  EXPECT_NEAR(Dipole(Material::preset("marble", 1.5)).channel[0].total_diffuse_reflectance(),
              0.830191, 1e-6);
  EXPECT_NEAR(Dipole(Material::preset("skimmilk", 1.3)).channel[0].total_diffuse_reflectance(),
              0.814946, 1e-6);
  EXPECT_NEAR(Dipole(Material::preset("ketchup", 1.3)).channel[2].total_diffuse_reflectance(),
              0.001830, 1e-6);
  const Dipole spectralon(Material::preset("spectralon", 1.3));
  for (const auto& ch : spectralon.channel) EXPECT_DOUBLE_EQ(ch.total_diffuse_reflectance(), 1.0);
}

TEST(Dipole, DiscIntegralEqualsClosedForm) {
  for (const char* name : {"marble", "skimmilk", "ketchup", "spectralon"}) {
    const Dipole dipole(Material::preset(name, 1.3));
    for (const auto& ch : dipole.channel) {
      for (double rho : {0.1 * ch.z_r, ch.z_r, 0.5, 2.0, 20.0}) {
        const double r0 = 1e-9 * ch.z_r;
        const double numeric = ch.Rd(0) * M_PI * r0 * r0 + test::radial_integral(ch, r0, rho);
        EXPECT_NEAR(numeric / ch.disc_reflectance(rho), 1.0, 1e-6) << name << " rho " << rho;
      }
    }
  }
}

TEST(Dipole, RdIsPositiveFiniteAndDecreasing) {
  for (const std::string& name : Material::preset_names()) {
    for (double scale : {1e-3, 1.0, 1e3}) {  // the same medium seen at very different scales
      Material m = Material::preset(name, 1.3);
      for (int c = 0; c < 3; ++c) {
        m.sigma_a[c] *= scale;
        m.sigma_s_prime[c] *= scale;
      }
      const Dipole dipole(m);
      for (const auto& ch : dipole.channel) {
        double previous = ch.Rd(0.0);
        ASSERT_TRUE(std::isfinite(previous) && previous > 0.0) << name;
        for (double r = 1e-6 * ch.z_r; r < 1e4 * ch.z_v; r *= 1.5) {
          const double rd = ch.Rd(r);
          ASSERT_TRUE(std::isfinite(rd)) << name << " r " << r;
          ASSERT_GE(rd, 0.0) << name << " r " << r;
          ASSERT_LE(rd, previous) << name << " r " << r;
          previous = rd;
        }
      }
    }
  }
}

TEST(Dipole, ReciprocalOnAPlane) {
  const DipoleChannel ch = Dipole(Material::preset("marble")).channel[1];
  const Eigen::Vector3d n(0, 0, 1), a(0.3, -0.2, 0), b(-1.1, 0.7, 0);
  auto rd = [&](const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
    return ch.Rd_from_distances((from - ch.z_r * n - to).norm(), (from + ch.z_v * n - to).norm());
  };
  EXPECT_DOUBLE_EQ(rd(a, b), rd(b, a));
  EXPECT_DOUBLE_EQ(rd(a, b), ch.Rd((a - b).norm()));
}

TEST(Dipole, SupportRadiusMeetsItsTolerance) {
  for (const char* name : {"marble", "skimmilk", "ketchup", "spectralon", "cream"}) {
    const Dipole dipole(Material::preset(name, 1.3));
    for (const auto& ch : dipole.channel) {
      for (double fraction : {1e-2, 1e-4, 1e-6}) {
        const double rho = ch.support_radius(fraction);
        ASSERT_TRUE(std::isfinite(rho) && rho > 0.0) << name;
        const double total = ch.total_diffuse_reflectance();
        // Beyond rho at most `fraction` of the total, by independent quadrature ...
        const double tail = total - (ch.Rd(0) * M_PI * 1e-18 * ch.z_r * ch.z_r +
                                     test::radial_integral(ch, 1e-9 * ch.z_r, rho));
        EXPECT_LE(tail / total, fraction * (1 + 1e-3)) << name << " " << fraction;
        // ... and the radius is the smallest such: 1 % less leaves more than the fraction out.
        EXPECT_GT(ch.tail_reflectance(0.99 * rho), fraction * total) << name;
      }
    }
  }
}

TEST(Dipole, TermDerivativesMatchFiniteDifferences) {
  for (double s : {0.0, 0.1, 3.0}) {
    for (double d : {0.05, 0.5, 5.0}) {
      const double h = 1e-5 * d;
      const DipoleTerm t = dipole_term(0.4, s, d);
      const DipoleTerm lo = dipole_term(0.4, s, d - h), hi = dipole_term(0.4, s, d + h);
      EXPECT_NEAR(t.d1, (hi.value - lo.value) / (2 * h), 1e-6 * std::fabs(t.d1));
      EXPECT_NEAR(t.d2, (hi.d1 - lo.d1) / (2 * h), 1e-6 * std::fabs(t.d2));
    }
  }
}

}  // namespace
}  // namespace sss
