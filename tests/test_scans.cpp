// The reference and the grid method on the shared Stanford scans (../shared/data), in marble
// at 1000 mm per unit (about 150 mm tall). Each test skips when its file is absent.
#include <gtest/gtest.h>

#include <cstdio>

#include "error_metric.h"
#include "reference_renderer.h"
#include "scan_io.h"

namespace sss {
namespace {

const std::vector<Light> kLight{{Eigen::Vector3d(0.4, 0.8, 0.45), 1.0}};

SurfelCloud load_or_skip(const char* name) {
  const std::string path = test::shared_data(name);
  if (path.empty()) return {};
  return test::load_ply_mesh(path);
}

void print_stats(const char* label, const RadianceStats& s) {
  std::printf("[ scan ] %s: %zu surfels, %zu lit cells, texel %.3f mm (%dx%d map), "
              "near field to %.2f mm (%zu weights), far field %s; %.1f s geometry + "
              "%.1f s light + %.1f s tree + %.1f s surfels\n",
              label, s.surfels, s.lit_cells, s.texel_mm, s.map_width, s.map_height,
              s.near_reach_mm, s.near_entries, s.far_field ? "beyond" : "none", s.seconds_geometry,
              s.seconds_light, s.seconds_tree, s.seconds_surfels);
}

// Halving the default source spacing (texels of z_r / 8 instead of z_r / 4, four times the
// samples) must change the bunny's radiance by less than 0.5 % mean: the reference has converged.
TEST(Scans, ReferenceConvergesOnTheBunny) {
  const SurfelCloud bunny = load_or_skip("stanford_bunny.ply");
  if (bunny.empty()) GTEST_SKIP() << "../shared/data/stanford_bunny.ply is absent";
  const Material marble = Material::preset("marble", 1.3, 1000.0);
  ReferenceSettings coarse, fine;
  fine.light_map.texel_per_radius = 0.5 * coarse.light_map.texel_per_radius;
  fine.irradiance_samples = 2 * coarse.irradiance_samples;
  const SurfelRadiance a = render_reference(bunny, marble, kLight, coarse);
  const SurfelRadiance b = render_reference(bunny, marble, kLight, fine);
  print_stats("bunny reference, default texel", a.stats);
  print_stats("bunny reference, half the texel", b.stats);
  const ErrorStats change = compare_radiance(a.B, b.B);
  std::printf("[ scan ] bunny reference, default texel against half of it: %s\n", change.summary().c_str());
  EXPECT_LT(change.mean, 0.005);
}

}  // namespace
}  // namespace sss
