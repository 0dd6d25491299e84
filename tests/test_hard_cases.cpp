// Hard inputs (no absorption, eta 1, tiny and huge kernels, far origins, thin parts, bad
// normals): each gives finite, correct values or a clear refusal.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "camera_view.h"
#include "fresnel.h"
#include "procedural_shapes.h"
#include "radial_kernel.h"
#include "reference_renderer.h"

namespace sss {
namespace {

const std::vector<Light> kTopLight{{Eigen::Vector3d(0, 0, 1), 1.0}};

// For tests of robustness rather than accuracy: coarser light maps, fewer samples per cell.
ReferenceSettings quick() {
  ReferenceSettings s;
  s.light_map.texel_per_radius = 0.5;
  s.irradiance_samples = 16;
  return s;
}

void expect_finite_nonnegative(const std::vector<Rgb>& B) {
  for (const Rgb& v : B)
    for (double x : v) {
      ASSERT_TRUE(std::isfinite(x));
      ASSERT_GE(x, 0.0);
    }
}

std::size_t centre_of(const SurfelCloud& cloud) {
  std::size_t centre = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i)
    if (cloud.positions[i].norm() < cloud.positions[centre].norm()) centre = i;
  return centre;
}

double max_relative_difference(const std::vector<Rgb>& a, const std::vector<Rgb>& b) {
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (int c = 0; c < 3; ++c)
      if (b[i][c] > 0) worst = std::max(worst, std::fabs(a[i][c] / b[i][c] - 1));
  return worst;
}

// Without absorption the kernel has no exponential decay; the centre of a disc-shaped slab of
// radius rho must still meet the closed-form disc integral.
TEST(HardCases, NoAbsorption) {
  const Material m = Material::custom({0, 0, 0}, {1.0, 2.0, 4.0}, 1.3);
  const Dipole dipole(m);
  const double rho = 60.0;
  const SurfelCloud slab = make_slab(rho, 1.0);
  ReferenceSettings at_centre;
  at_centre.receivers = {centre_of(slab)};
  const ReferenceSolver solver(slab, m, kTopLight, at_centre);
  const Rgb B = solver.B(0);
  for (int c = 0; c < 3; ++c) {
    const double Ft0 = fresnel_transmittance(1.3, 1.0);
    EXPECT_NEAR(B[c] / (Ft0 * dipole.channel[c].disc_reflectance(rho) / M_PI), 1.0, 0.01) << c;
  }
}

// A single surfel lit head-on is a disc of sources: the closed-form disc integral again.
TEST(HardCases, OnePoint) {
  const Material m = Material::preset("marble");
  SurfelCloud one;
  one.positions = {{3, -2, 7}};
  one.normals = {{0, 0, 1}};
  one.radius = 5.0;
  one.validate();
  const SurfelRadiance r = render_reference(one, m, kTopLight);
  const Dipole dipole(m);
  for (int c = 0; c < 3; ++c) {
    const double expected =
        fresnel_transmittance(1.3, 1.0) * dipole.channel[c].disc_reflectance(5.0) / M_PI;
    EXPECT_NEAR(r.B[0][c] / expected, 1.0, 0.01) << c;
  }
}

TEST(HardCases, EmptyCloud) {
  const SurfelCloud empty;
  const Material m = Material::preset("marble");
  EXPECT_TRUE(render_reference(empty, m, kTopLight).B.empty());
  const LinearImage image = render_view(empty, m, {}, OrthoCamera{});
  EXPECT_EQ(image.max_value(), 0.0);
}

TEST(HardCases, LineCloud) {
  const SurfelCloud line = make_line(200, 0.1);
  const Material m = Material::preset("marble");
  const SurfelRadiance ref = render_reference(line, m, kTopLight);
  expect_finite_nonnegative(ref.B);
  EXPECT_GT(ref.B[100][0], 0.0);
}

TEST(HardCases, DuplicatePointsAndBadNormals) {
  SurfelCloud sphere = make_sphere(10, 0.5);
  const std::size_t n = sphere.size();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < n; i += 10) {  // duplicates, unnormalised, NaN, Inf and zero normals
    sphere.positions.push_back(sphere.positions[i]);
    sphere.normals.push_back(3.0 * sphere.normals[i]);
  }
  sphere.positions.push_back({0, 0, 10});
  sphere.normals.push_back({nan, 0, 1});
  sphere.positions.push_back({0, 0, 10});
  sphere.normals.push_back({0, 0, std::numeric_limits<double>::infinity()});
  sphere.positions.push_back({0, 0, 10});
  sphere.normals.push_back({0, 0, 0});
  const CloudReport report = sphere.validate();
  EXPECT_EQ(report.dropped(), 3u);
  const SurfelRadiance r = render_reference(sphere, Material::preset("marble"), kTopLight, quick());
  expect_finite_nonnegative(r.B);
}

// The light lights the side of each surfel it sees, so flipping half the normals of a flat
// slab changes no radiance. On a sphere the near field's bend with the surface (first order in
// z kappa, radial_kernel.h) follows the side the normal says the material is on, so
// there a flipped normal changes B by at most that bend, weighted by the kernel over the near
// field's reach (1.3 % for marble on a 10 mm sphere).
TEST(HardCases, InconsistentlyOrientedNormals) {
  const Material m = Material::preset("marble");
  const SurfelCloud slab = make_slab(10, 0.5);
  SurfelCloud flipped_slab = slab;
  for (std::size_t i = 0; i < flipped_slab.size(); i += 2)
    flipped_slab.normals[i] = -flipped_slab.normals[i];
  EXPECT_LT(max_relative_difference(render_reference(flipped_slab, m, kTopLight, quick()).B,
                                    render_reference(slab, m, kTopLight, quick()).B),
            1e-9);
  const SurfelCloud sphere = make_sphere(10, 0.5);
  SurfelCloud flipped = sphere;
  for (std::size_t i = 0; i < flipped.size(); i += 2) flipped.normals[i] = -flipped.normals[i];
  const SurfelRadiance a = render_reference(sphere, m, kTopLight, quick());
  const SurfelRadiance b = render_reference(flipped, m, kTopLight, quick());
  double largest_bend = 0.0;
  const Dipole dipole(m);
  const double reach = NearFarSplit::choose(dipole, sphere.radius, 1e-7).reach;
  for (int c = 0; c < 3; ++c) {
    const DipoleChannel& ch = dipole.channel[c];
    double spread = 0.0, total = 0.0;
    for (double rho = 0.0005; rho < reach; rho += 0.001) {
      const double w = ch.Rd(rho) * rho;
      spread += w * std::fabs(RadialKernel::bend(dipole, rho, 0.1)[c] -
                              RadialKernel::bend(dipole, rho, -0.1)[c]);
      total += w;
    }
    largest_bend = std::max(largest_bend, spread / total);
  }
  std::printf("[ hard ] half the normals flipped on a 10 mm sphere: B differs by at most %.2f %%, "
              "the bend's spread %.2f %%\n", 100 * max_relative_difference(b.B, a.B),
              100 * largest_bend);
  EXPECT_LT(max_relative_difference(b.B, a.B), largest_bend);
}

// In green, ketchup's diffusion length is 0.57 mm and skim milk's 10 mm: on the same sphere,
// skim milk carries far more light into the shadowed half.
TEST(HardCases, TinyAndHugeKernelsOnOneModel) {
  const SurfelCloud sphere = make_sphere(15, 0.5);
  double shadow_ratio[2];
  int k = 0;
  for (const char* name : {"ketchup", "skimmilk"}) {
    const SurfelRadiance r = render_reference(sphere, Material::preset(name), kTopLight, quick());
    expect_finite_nonnegative(r.B);
    double lit = 0, dark = 0;
    for (std::size_t i = 0; i < sphere.size(); ++i)
      (sphere.normals[i].z() > 0 ? lit : dark) += r.B[i][1];
    shadow_ratio[k++] = dark / lit;
  }
  std::printf("[ hard ] green light in the shadowed half over the lit half: ketchup %.4f, "
              "skim milk %.4f\n", shadow_ratio[0], shadow_ratio[1]);
  EXPECT_GT(shadow_ratio[1], 3 * shadow_ratio[0]);
}

// The same object in mm, in m with 1000 mm per unit, and shifted by 1e6 units. At the default
// texel no source is split; coarser texels split sources near receivers with a count that
// steps with distance, and a 1e-10 rounding difference can then flip one step (3e-5 seen
// with texels of one z_r).
TEST(HardCases, UnitsAndFarOrigins) {
  const SurfelCloud mm = make_torus(20, 6, 0.5);
  SurfelCloud m = mm, far = mm;
  for (auto& p : m.positions) p /= 1000.0;
  m.radius /= 1000.0;
  for (auto& p : far.positions) p += Eigen::Vector3d(1e6, -2e6, 1e6);
  const std::vector<Light> light{{Eigen::Vector3d(1, -1, 2), 1.0}};
  const SurfelRadiance a = render_reference(mm, Material::preset("marble", 1.3, 1.0), light);
  const SurfelRadiance b = render_reference(m, Material::preset("marble", 1.3, 1000.0), light);
  const SurfelRadiance c = render_reference(far, Material::preset("marble", 1.3, 1.0), light);
  EXPECT_LT(max_relative_difference(b.B, a.B), 1e-6);
  EXPECT_LT(max_relative_difference(c.B, a.B), 1e-6);
}

// Light from behind the camera's side: the thin tube of a torus glows through.
TEST(HardCases, BackLightShinesThroughThinParts) {
  const SurfelCloud torus = make_torus(20, 2, 0.25);
  const std::vector<Light> back{{Eigen::Vector3d(0, 0, -1), 1.0}};
  const SurfelRadiance r = render_reference(torus, Material::preset("skimmilk"), back, quick());
  expect_finite_nonnegative(r.B);
  double top = 0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < torus.size(); ++i)
    if (torus.normals[i].z() > 0.9) {
      top += r.B[i][0];
      ++count;
    }
  EXPECT_GT(top / count, 0.05);  // the unlit top gets a clear share of the lit bottom's ~0.25
}

TEST(HardCases, GrazingLightLightsNothing) {
  const SurfelCloud slab = make_slab(10, 0.5);
  const SurfelRadiance r =
      render_reference(slab, Material::preset("marble"), {{Eigen::Vector3d(1, 0, 0), 1.0}});
  for (const Rgb& v : r.B) EXPECT_EQ(v[0], 0.0);
}

TEST(HardCases, IndexOfOneHasNoFresnelLoss) {
  const Material m = Material::preset("marble", 1.0);
  const Dipole dipole(m);
  const double rho = dipole.max_support_radius(1e-3);
  const SurfelCloud slab = make_slab(rho, 0.5);
  ReferenceSettings at_centre;
  at_centre.receivers = {centre_of(slab)};
  const ReferenceSolver solver(slab, m, kTopLight, at_centre);
  const Rgb B = solver.B(0);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(B[c] / (dipole.channel[c].total_diffuse_reflectance() / M_PI), 1.0, 0.01);
}

TEST(HardCases, BadLightsAndSettingsAreRefused) {
  const SurfelCloud sphere = make_sphere(5, 0.5);
  const Material m = Material::preset("marble");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(render_reference(sphere, m, {{Eigen::Vector3d::Zero(), 1.0}}), std::invalid_argument);
  EXPECT_THROW(render_reference(sphere, m, {{Eigen::Vector3d(nan, 0, 1), 1.0}}), std::invalid_argument);
  EXPECT_THROW(render_reference(sphere, m, {{Eigen::Vector3d(0, 0, 1), -1.0}}), std::invalid_argument);
  ReferenceSettings bad;
  bad.light_map.texel_per_radius = 0.0;
  EXPECT_THROW(render_reference(sphere, m, kTopLight, bad), std::invalid_argument);
  ReferenceSettings no_samples;
  no_samples.irradiance_samples = 0;
  EXPECT_THROW(render_reference(sphere, m, kTopLight, no_samples), std::invalid_argument);
  ReferenceSettings outside;
  outside.receivers = {sphere.size()};
  EXPECT_THROW(render_reference(sphere, m, kTopLight, outside), std::invalid_argument);
  // No light is not an error: everything is black.
  for (const Rgb& v : render_reference(sphere, m, {}).B) EXPECT_EQ(v[0], 0.0);
}

TEST(HardCases, ImageHasNoNaNAndBlackBackground) {
  const SurfelCloud torus = make_torus(20, 6, 0.5);
  const Material m = Material::preset("marble");
  const SurfelRadiance r = render_reference(torus, m, kTopLight, quick());
  OrthoCamera camera;
  camera.width = camera.height = 64;
  camera.view_direction = {0, -1, 1};
  const LinearImage image = render_view(torus, m, r.B, camera);
  std::size_t covered = 0;
  for (std::size_t k = 0; k < image.radiance.size(); ++k) {
    for (double v : image.radiance[k]) ASSERT_TRUE(std::isfinite(v));
    if (image.covered[k]) ++covered;
    else EXPECT_EQ(image.radiance[k][0], 0.0);
  }
  EXPECT_GT(covered, 500u);
}

}  // namespace
}  // namespace sss
