// The flat slab: far from its edge, lit and seen straight on, the outgoing
// radiance is Ft(0) E Ft(0) R_total / pi. The reference must meet it whatever the surfel
// spacing, from z_r / 4 to 100 z_r (a room scan's spacing in marble).
#include <gtest/gtest.h>

#include <algorithm>
#include <tuple>

#include "fresnel.h"
#include "procedural_shapes.h"
#include "reference_renderer.h"
#include "splat_coverage.h"

namespace sss {
namespace {

class Slab : public ::testing::TestWithParam<std::tuple<const char*, double>> {};

std::size_t centre_of(const SurfelCloud& cloud) {
  std::size_t centre = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i)
    if (cloud.positions[i].norm() < cloud.positions[centre].norm()) centre = i;
  return centre;
}

void expect_closed_form(const Material& material, double spacing,
                        const ReferenceSettings& settings, const char* label) {
  const Dipole dipole(material);
  // Big enough that the slab's finite size leaves out at most 0.1 % of the total.
  const double slab_radius = dipole.max_support_radius(1e-3) + 2 * spacing;
  const SurfelCloud slab = make_slab(slab_radius, spacing);
  const double E = 2.0;
  ReferenceSettings at_centre = settings;
  at_centre.receivers = {centre_of(slab)};
  const ReferenceSolver solver(slab, material, {{Eigen::Vector3d(0, 0, 1), E}}, at_centre);
  const Rgb B = solver.B(0);
  for (int c = 0; c < 3; ++c) {
    const double Ft0 = fresnel_transmittance(material.eta[c], 1.0);
    const double expected = Ft0 * E * Ft0 * dipole.channel[c].total_diffuse_reflectance() / M_PI;
    const double Lo = Ft0 * B[c];
    EXPECT_NEAR(Lo / expected, 1.0, 0.01) << label << " channel " << c;
    std::printf("[ slab ] %-9s spacing %8.3f mm texel %.3f mm near field to %.2f mm%s channel "
                "%d: Lo %.6g closed form %.6g (%+.4f %%)\n", label, spacing, solver.stats().texel_mm,
                solver.stats().near_reach_mm, solver.stats().far_field ? "" : " (all)", c, Lo, expected,
                100 * (Lo / expected - 1));
  }
}

TEST_P(Slab, CentreMatchesClosedForm) {
  const char* name = std::get<0>(GetParam());
  const Material material = Material::preset(name, 1.3);
  const Dipole dipole(material);
  const double z_r = std::max({dipole.channel[0].z_r, dipole.channel[1].z_r, dipole.channel[2].z_r});
  expect_closed_form(material, std::get<1>(GetParam()) * z_r, ReferenceSettings{}, name);
}

INSTANTIATE_TEST_SUITE_P(
    Spacings, Slab,
    ::testing::Combine(::testing::Values("marble", "skimmilk", "ketchup"),
                       ::testing::Values(0.25, 1.0, 4.0, 20.0, 100.0)),
    [](const auto& info) {
      return std::string(std::get<0>(info.param)) + "_" +
             std::to_string(static_cast<int>(100 * std::get<1>(info.param))) + "pct_z_r";
    });

// The same slab sampled at random (Poisson, as a mesh sampled at random), radii as the product
// chooses them (splat_coverage.h): each cell is the whole area its surfel stands for, so the
// mean over the receivers near the centre meets the closed form as the regular grid does
// (1 %; with cells cut at 1.5 spacings, 17 % of the surface lay in no cell and B was 15 % low
// at z_r / 4). Single receivers scatter by up to 5 % near one z_r (printed, not asserted: the
// far field places each cell's light at its surfel, not at its cell's centroid; no bar is set
// for it yet).
class RandomSlab : public ::testing::TestWithParam<std::tuple<const char*, double>> {};

TEST_P(RandomSlab, CentreMeetsClosedFormOnAverage) {
  const char* name = std::get<0>(GetParam());
  const Material material = Material::preset(name, 1.3);
  const Dipole dipole(material);
  const double z_r = std::max({dipole.channel[0].z_r, dipole.channel[1].z_r, dipole.channel[2].z_r});
  const double spacing = std::get<1>(GetParam()) * z_r;
  const double support = dipole.max_support_radius(1e-3);
  // Receivers within `centre`; beyond them the kernel's reach and ten spacings of margin.
  const double centre = std::max(0.3 * support, 4 * spacing);
  SurfelCloud slab = make_random_slab(support + centre + 10 * spacing, spacing, 3);
  assign_splat_radii(slab);
  ReferenceSettings settings;
  for (std::size_t i = 0; i < slab.size() && settings.receivers.size() < 24; ++i)
    if (slab.positions[i].norm() < centre) settings.receivers.push_back(i);
  ASSERT_GE(settings.receivers.size(), 8u);
  const double E = 1.0;
  const ReferenceSolver solver(slab, material, {{Eigen::Vector3d(0, 0, 1), E}}, settings);
  for (int c = 0; c < 3; ++c) {
    const double Ft0 = fresnel_transmittance(material.eta[c], 1.0);
    const double expected = E * Ft0 * dipole.channel[c].total_diffuse_reflectance() / M_PI;
    double sum = 0.0, worst = 0.0;
    for (std::size_t k = 0; k < settings.receivers.size(); ++k) {
      const double ratio = solver.B(k)[c] / expected;
      sum += ratio;
      worst = std::max(worst, std::fabs(ratio - 1.0));
    }
    const double mean = sum / settings.receivers.size();
    EXPECT_NEAR(mean, 1.0, 0.01) << name << " channel " << c;
    std::printf("[ random slab ] %-9s spacing %8.3f mm, %zu points, channel %d: B / closed form "
                "%+.3f %% mean over %zu receivers, worst %.2f %%\n", name, spacing, slab.size(), c,
                100 * (mean - 1), settings.receivers.size(), 100 * worst);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Spacings, RandomSlab,
    ::testing::Combine(::testing::Values("marble", "ketchup"),
                       ::testing::Values(0.25, 1.0, 4.0, 20.0, 100.0)),
    [](const auto& info) {
      return std::string(std::get<0>(info.param)) + "_" +
             std::to_string(static_cast<int>(100 * std::get<1>(info.param))) + "pct_z_r";
    });

// A coarse light map (texels of a whole disc radius) changes nothing on a lit plane: the
// irradiance is each cell's own, the map only says which points the light reaches.
TEST(SlabCoarseMap, TexelsOfADiscRadiusStillMeetClosedForm) {
  const Material material = Material::preset("marble", 1.5);
  ReferenceSettings coarse;
  coarse.light_map.texel_per_radius = 1.0;
  expect_closed_form(material, Dipole(material).min_z_r(), coarse, "marble coarse map");
}

// A scan's isolated point (through a window, between flight lines) gets a cell and a disc tens
// of metres wide; the near field's kernel table must still resolve the kernel at every
// receiver. It once spread its samples over the widest cell's reach (on the airborne tile a
// cell of 103 m, so samples 12.7 mm apart), and skin's green and blue came out 10 to 1000
// times too dark there, in both methods (here, before: -2 / -16 / -47 %). Skin1 on four patches of a plane 50 mm apart (a scan
// in metres: the kernel ends inside each receiver's cell), 30 m around an isolated point.
TEST(SlabWithAnIsolatedPoint, CentreStillMeetsClosedForm) {
  const Material skin = Material::preset("skin1", 1.3);
  const Dipole dipole(skin);
  const double spacing = 50.0, away = 30000.0;
  const SurfelCloud patch = make_slab(8 * spacing, spacing);
  SurfelCloud plane;
  const Eigen::Vector3d centres[4] = {{away, 0, 0}, {-away, 0, 0}, {0, away, 0}, {0, -away, 0}};
  for (const Eigen::Vector3d& c : centres)
    for (std::size_t i = 0; i < patch.size(); ++i) {
      plane.positions.push_back(patch.positions[i] + c);
      plane.normals.push_back(patch.normals[i]);
    }
  plane.positions.push_back(Eigen::Vector3d::Zero());
  plane.normals.push_back(Eigen::Vector3d::UnitZ());
  plane.radius = patch.radius;
  assign_splat_radii(plane);
  plane.validate();
  ReferenceSettings at_centre;
  at_centre.receivers = {centre_of(patch)};  // the first patch's centre
  at_centre.light_map.max_map_size = 1024;   // a plane lit straight on: nothing to shadow
  const double E = 1.0;
  const ReferenceSolver solver(plane, skin, {{Eigen::Vector3d(0, 0, 1), E}}, at_centre);
  const Rgb B = solver.B(0);
  std::printf("[ slab ] isolated point: disc radius %.0f mm, cells' radius %.0f mm; %.1f s geometry, %.1f s light\n",
              plane.radii.back(), plane.radius, solver.stats().seconds_geometry, solver.stats().seconds_light);
  for (int c = 0; c < 3; ++c) {
    const double Ft0 = fresnel_transmittance(skin.eta[c], 1.0);
    const double expected = E * Ft0 * dipole.channel[c].total_diffuse_reflectance() / M_PI;
    std::printf("[ slab ] skin1, patches 50 mm apart around an isolated point, channel %d: B "
                "%.6g closed form %.6g (%+.4f %%)\n", c, B[c], expected,
                100 * (B[c] / expected - 1));
    EXPECT_NEAR(B[c] / expected, 1.0, 0.01) << "channel " << c;
  }
}

}  // namespace
}  // namespace sss
