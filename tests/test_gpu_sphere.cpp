// The GPU path's defaults on curved surfaces at every scale: a 5 m sphere against its local
// closed form, the same points at 50 mm and 2 mm against the CPU reference, and a 30 mm sphere
// at two samplings against itself.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "error_metric.h"
#include "gpu_scene.h"
#include "procedural_shapes.h"
#include "reference_cache.h"
#include "reference_renderer.h"
#include "sphere_cases.h"

namespace sss::test {
namespace {

const Eigen::Vector3d kAlongZ(0, 0, 1);

// 125,000 points on a Fibonacci lattice of radius 5000 units (48 units apart), lit and seen
// along +z.
const SurfelCloud& lattice() {
  static const SurfelCloud sphere = make_fibonacci_sphere(5000.0, 125000);
  return sphere;
}

std::vector<Rgb> at(const std::vector<Rgb>& B, const std::vector<std::size_t>& ids) {
  std::vector<Rgb> out;
  for (std::size_t i : ids) out.push_back(B[i]);
  return out;
}

// At 1 mm per unit (R = 5 m, points 48 mm apart, far beyond every kernel) B is the local closed
// form Ft cos R_total / pi at the points with cos(theta) > 0.2.
class GpuSphereClosedForm : public ::testing::TestWithParam<const char*> {};

TEST_P(GpuSphereClosedForm, FiveMetreSphereMeetsTheLocalClosedForm) {
  const Material material = Material::preset(GetParam(), 1.3);
  const SurfelCloud& sphere = lattice();
  const std::vector<std::size_t> ids = sample_of(sphere, 2000, 7, kAlongZ, 0.2);
  GpuScene scene(sphere, material, {{kAlongZ, 1.0}});
  const std::vector<Rgb> B = scene.render_B();
  ASSERT_EQ(B.size(), sphere.size());
  std::vector<Rgb> expected;
  for (std::size_t i : ids) expected.push_back(local_closed_form(material, sphere.normals[i], kAlongZ));
  const ErrorStats e = compare_radiance(at(B, ids), expected);
  std::printf("[ gpu sphere ] %s, R 5 m, %zu points %.0f mm apart: against Ft cos R_total / pi %s\n",
              GetParam(), sphere.size(), sphere.mean_spacing(), e.summary().c_str());
  EXPECT_LT(e.mean, 0.01);
  EXPECT_LT(e.p99, 0.05);
}

INSTANTIATE_TEST_SUITE_P(Materials, GpuSphereClosedForm,
                         ::testing::Values("marble", "skimmilk", "ketchup"),
                         [](const auto& info) { return std::string(info.param); });

// The same points at 0.01 and 0.0004 mm per unit: R = 50 mm (0.48 mm apart, about z_r) and
// R = 2 mm (0.02 mm apart, the kernel wider than the sphere), against the reference (cached)
// at the points the reference does not call dark. At 2 mm nearly every cell is summed alone
// (no group of the far field stays clear of the dipole's clamp): minutes per material on
// llvmpipe. Ketchup at 2 mm (z_r of red twice the sphere's radius) runs only with
// SSS_LONG_TESTS=1: about 7 minutes with its reference uncached (GpuSphereWalk below covers
// the same regime in seconds).
struct Scaled {
  const char* material;
  double mm_per_unit;
  bool long_run;
};

void PrintTo(const Scaled& s, std::ostream* os) {
  *os << s.material << " at " << s.mm_per_unit << " mm per unit";
}

// The GPU's B and the reference's (cached) at `count` points of `sphere` lit along +z.
struct AgainstReference {
  std::vector<std::size_t> receivers;
  std::vector<Rgb> B, reference;
  ErrorStats error;
};

AgainstReference gpu_against_reference(const SurfelCloud& sphere, const Material& material,
                                       std::size_t count, unsigned seed) {
  AgainstReference r;
  ReferenceSettings settings;
  settings.receivers = r.receivers = sample_of(sphere, count, seed);
  r.reference = cached_reference(SSS_TEST_REFERENCE_CACHE, sphere, material, {{kAlongZ, 1.0}},
                                 settings).B;
  GpuScene scene(sphere, material, {{kAlongZ, 1.0}});
  r.B = scene.render_B();
  if (r.B.size() == sphere.size())
    r.error = compare_radiance(at(r.B, r.receivers), at(r.reference, r.receivers));
  return r;
}

class GpuSphereAgainstReference : public ::testing::TestWithParam<Scaled> {};

TEST_P(GpuSphereAgainstReference, SamePointsAtAnotherScale) {
  if (GetParam().long_run && !std::getenv("SSS_LONG_TESTS"))
    GTEST_SKIP() << "a long case on llvmpipe; set SSS_LONG_TESTS=1 to run it";
  const Material material = Material::preset(GetParam().material, 1.3, GetParam().mm_per_unit);
  const SurfelCloud& sphere = lattice();
  const AgainstReference r = gpu_against_reference(sphere, material, 2000, 11);
  ASSERT_EQ(r.B.size(), sphere.size());
  const ErrorStats& e = r.error;
  // Per channel, summed B over summed reference B: a bias that dark points cannot swamp.
  double sums[2][3] = {{0, 0, 0}, {0, 0, 0}};
  for (std::size_t i : r.receivers)
    for (int c = 0; c < 3; ++c) {
      sums[0][c] += r.B[i][c];
      sums[1][c] += r.reference[i][c];
    }
  double bias[3];
  for (int c = 0; c < 3; ++c) bias[c] = 100.0 * (sums[0][c] / sums[1][c] - 1.0);
  std::printf("[ gpu sphere ] %s, R %.0f mm, points %.3f mm apart: against the reference %s; "
              "summed B per channel %+.2f %+.2f %+.2f %% off\n",
              GetParam().material, 5000 * GetParam().mm_per_unit,
              sphere.mean_spacing() * GetParam().mm_per_unit, e.summary().c_str(),
              bias[0], bias[1], bias[2]);
  EXPECT_LT(e.mean, 0.01);
  EXPECT_LT(e.p99, 0.05);
}

INSTANTIATE_TEST_SUITE_P(
    Scales, GpuSphereAgainstReference,
    ::testing::Values(Scaled{"marble", 0.01, false}, Scaled{"skimmilk", 0.01, false},
                      Scaled{"ketchup", 0.01, false}, Scaled{"marble", 0.0004, false},
                      Scaled{"skimmilk", 0.0004, false}, Scaled{"ketchup", 0.0004, true}),
    [](const auto& info) {
      return std::string(info.param.material) + (info.param.mm_per_unit > 0.001 ? "_50mm" : "_2mm");
    });

// llvmpipe ends a fragment's loops after 65,535 iterations in all. A 2 mm ketchup sphere of
// 32,000 points opens every cell of the far field's walk (z_r of red is twice the radius), so
// each walk visits the whole subtree of a level-7 root: 16,384 cells and 5,461 groups. When
// each node cost a few loop iterations, those walks were cut short and B came out 45 % low in
// every channel, while 8,000 points (one smaller root) were exact.
TEST(GpuSphereWalk, AWalkThroughAWholeRootIsNotCutShort) {
  const SurfelCloud sphere = make_fibonacci_sphere(5000.0, 32000);
  const AgainstReference r =
      gpu_against_reference(sphere, Material::preset("ketchup", 1.3, 0.0004), 400, 5);
  ASSERT_EQ(r.B.size(), sphere.size());
  const ErrorStats& e = r.error;
  std::printf("[ gpu sphere ] ketchup, R 2 mm, 32,000 points: against the reference %s\n",
              e.summary().c_str());
  EXPECT_LT(e.mean, 0.01);
  EXPECT_LT(e.p99, 0.05);
}

// The truth does not depend on the sampling: a 30 mm sphere sampled 1.26 mm apart (the
// Stanford bunny's spacing) and 0.4 mm apart gives the same B at the same place.
class GpuSamplingInvariance : public ::testing::TestWithParam<const char*> {};

TEST_P(GpuSamplingInvariance, ThirtyMillimetreSphereAtTwoSamplings) {
  const TwoSamplings two = thirty_millimetre_spheres();
  const SurfelCloud &coarse = two.coarse, &fine = two.fine;
  const Material material = Material::preset(GetParam(), 1.3);
  const std::vector<Light>& light = two.light;
  const std::vector<std::size_t>& points = two.points;
  const auto& neighbours = two.neighbours;
  std::vector<Rgb> coarse_B, fine_B;
  {
    GpuScene scene(coarse, material, light);
    coarse_B = scene.render_B();
  }
  {
    GpuScene scene(fine, material, light);
    fine_B = scene.render_B();
  }
  const ErrorStats e =
      compare_radiance(at(coarse_B, points), fitted_at(coarse, points, fine, fine_B, neighbours));
  std::printf("[ gpu sampling ] %s, 30 mm sphere, %.2f mm against %.2f mm apart, at the same "
              "place: %s\n", GetParam(), coarse.mean_spacing(), fine.mean_spacing(),
              e.summary().c_str());
  EXPECT_LT(e.mean, 0.01);
  EXPECT_LT(e.p99, 0.05);
}

INSTANTIATE_TEST_SUITE_P(Materials, GpuSamplingInvariance,
                         ::testing::Values("marble", "skimmilk", "ketchup"),
                         [](const auto& info) { return std::string(info.param); });

}  // namespace
}  // namespace sss::test
