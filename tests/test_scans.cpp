// The reference and the grid method on the shared Stanford scans (../shared/data), in marble
// at 1000 mm per unit (about 150 mm tall). Each test skips when its file is absent.
#include <gtest/gtest.h>

#include <cstdio>

#include "error_metric.h"
#include "grid_renderer.h"
#include "reference_renderer.h"
#include "scan_io.h"

namespace sss {
namespace {

const std::vector<DirectionalLight> kLight{{Eigen::Vector3d(0.4, 0.8, 0.45), 1.0}};

SurfelCloud load_or_skip(const char* name) {
  const std::string path = test::shared_data(name);
  if (path.empty()) return {};
  return test::load_ply_mesh(path);
}

void print_stats(const char* label, const RadianceStats& s) {
  std::printf("[ scan ] %s: %zu surfels, %zu lit samples, texel %.3f mm (%dx%d map), "
              "%zu virtual points (level %d, %.2f mm), %.1f s sources + %.1f s tree + %.1f s "
              "virtual points + %.1f s surfels\n",
              label, s.surfels, s.lit_samples, s.texel_mm, s.map_width, s.map_height,
              s.virtual_points, s.grid_level, s.grid_spacing_mm, s.seconds_illumination,
              s.seconds_tree, s.seconds_virtual_points, s.seconds_surfels);
}

// Halving the default source spacing (texels of z_r / 8 instead of z_r / 4, four times the
// samples) must change the bunny's radiance by less than 0.5 % mean: the reference has converged.
TEST(Scans, ReferenceConvergesOnTheBunny) {
  const SurfelCloud bunny = load_or_skip("stanford_bunny.ply");
  if (bunny.empty()) GTEST_SKIP() << "../shared/data/stanford_bunny.ply is absent";
  const Material marble = Material::preset("marble", 1.3, 1000.0);
  ReferenceSettings coarse, fine;
  fine.illumination.texel_per_z_r = 0.5 * coarse.illumination.texel_per_z_r;
  const SurfelRadiance a = render_reference(bunny, marble, kLight, coarse);
  const SurfelRadiance b = render_reference(bunny, marble, kLight, fine);
  print_stats("bunny reference, default texel", a.stats);
  print_stats("bunny reference, half the texel", b.stats);
  const ErrorStats change = compare_radiance(a.B, b.B);
  std::printf("[ scan ] bunny reference, default texel against half of it: %s\n", change.summary().c_str());
  EXPECT_LT(change.mean, 0.005);
}

// The CPU grid method against the reference on the dragon (100,250 vertices).
TEST(Scans, GridMethodAgainstReferenceOnTheDragon) {
  const SurfelCloud dragon = load_or_skip("dragon_vrip_res2.ply.gz");
  if (dragon.empty()) GTEST_SKIP() << "../shared/data/dragon_vrip_res2.ply.gz is absent";
  const Material marble = Material::preset("marble", 1.3, 1000.0);
  const SurfelRadiance reference = render_reference(dragon, marble, kLight);
  print_stats("dragon reference", reference.stats);
  GridSettings paper;
  paper.near_field_cells = 0.0;
  const SurfelRadiance plain = render_grid(dragon, marble, kLight, paper);
  const ErrorStats plain_error = compare_radiance(plain.B, reference.B);
  print_stats("dragon grid, no near field (paper)", plain.stats);
  std::printf("[ scan ] dragon grid, no near field (paper): %s\n", plain_error.summary().c_str());
  const SurfelRadiance split = render_grid(dragon, marble, kLight);
  const ErrorStats split_error = compare_radiance(split.B, reference.B);
  print_stats("dragon grid, near field per surfel", split.stats);
  std::printf("[ scan ] dragon grid, near field per surfel: %s\n", split_error.summary().c_str());
  // This is the method the GPU path runs, so it is held to the GPU's goal (mean < 0.5 %,
  // p99 < 3 %); measured: mean 0.19 %, p99 2.5 %, while the paper's grid-only form is off by
  // 29 % mean, as the design notes predict for a kernel whose near field is finer than h.
  EXPECT_LT(split_error.mean, 0.005);
  EXPECT_LT(split_error.p99, 0.03);
}

}  // namespace
}  // namespace sss
