// The flat slab of DESIGN section 2: far from its edge, lit and seen straight on, the outgoing
// radiance is Ft(0) E Ft(0) R_total / pi. The sources are illumination-map texels, so the
// reference must meet it whatever the surfel spacing, from z_r / 4 to 4 z_r.
#include <gtest/gtest.h>

#include <algorithm>

#include "fresnel.h"
#include "procedural_shapes.h"
#include "reference_renderer.h"

namespace sss {
namespace {

struct SlabCase {
  const char* material;
  double spacing_in_z_r;  // surfel spacing over the largest z_r of the material
};

class Slab : public ::testing::TestWithParam<SlabCase> {};

void expect_closed_form(const Material& material, double spacing,
                        const IlluminationSettings& illumination, const char* label) {
  const Dipole dipole(material);
  // Big enough that the slab's finite size leaves out at most 0.1 % of the total.
  const double slab_radius = dipole.max_support_radius(1e-3) + 2 * spacing;
  const SurfelCloud slab = make_slab(slab_radius, spacing);
  const double E = 2.0;
  const ReferenceSolver solver(slab, material, {{Eigen::Vector3d(0, 0, 1), E}}, illumination,
                               SourceTreeSettings{});
  const Rgb B = solver.B_at(Eigen::Vector3d::Zero());
  for (int c = 0; c < 3; ++c) {
    const double Ft0 = fresnel_transmittance(material.eta[c], 1.0);
    const double expected = Ft0 * E * Ft0 * dipole.channel[c].total_diffuse_reflectance() / M_PI;
    const double Lo = Ft0 * B[c];
    EXPECT_NEAR(Lo / expected, 1.0, 0.01) << label << " channel " << c;
    std::printf("[ slab ] %-9s spacing %.3f mm texel %.3f mm channel %d: Lo %.6g closed form %.6g"
                " (%+.4f %%)\n", label, spacing, solver.stats().texel_mm, c, Lo, expected,
                100 * (Lo / expected - 1));
  }
}

TEST_P(Slab, CentreMatchesClosedForm) {
  const Material material = Material::preset(GetParam().material, 1.3);
  const Dipole dipole(material);
  const double z_r = std::max({dipole.channel[0].z_r, dipole.channel[1].z_r, dipole.channel[2].z_r});
  expect_closed_form(material, GetParam().spacing_in_z_r * z_r, IlluminationSettings{},
                     GetParam().material);
}

INSTANTIATE_TEST_SUITE_P(
    Spacings, Slab,
    ::testing::Values(SlabCase{"marble", 0.25}, SlabCase{"marble", 1}, SlabCase{"marble", 4},
                      SlabCase{"skimmilk", 0.25}, SlabCase{"skimmilk", 1},
                      SlabCase{"skimmilk", 4}, SlabCase{"ketchup", 0.25},
                      SlabCase{"ketchup", 1}, SlabCase{"ketchup", 4}),
    [](const auto& info) {
      return std::string(info.param.material) + "_" +
             std::to_string(static_cast<int>(100 * info.param.spacing_in_z_r)) + "pct_z_r";
    });

// A map too small for texels finer than z_r: each texel's area is then integrated by splitting
// it near the receiver, and the closed form still holds.
TEST(SlabCoarseMap, TexelsOfFourZrStillMeetClosedForm) {
  const Material material = Material::preset("marble", 1.5);
  const Dipole dipole(material);
  const double slab_radius = dipole.max_support_radius(1e-3);
  IlluminationSettings coarse;
  coarse.max_map_size = static_cast<int>(2 * slab_radius / (4 * dipole.min_z_r()));
  expect_closed_form(material, dipole.min_z_r(), coarse, "marble coarse map");
}

}  // namespace
}  // namespace sss
