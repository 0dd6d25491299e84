// Positional lights through the light-projection seam (a perspective light map): the CPU
// reference in the limit of a far point light, and the GPU path against the reference for a
// point light and a spot close to a torus, shadowing itself.
#include <gtest/gtest.h>

#include <cstdio>

#include "error_metric.h"
#include "gpu_scene.h"
#include "procedural_shapes.h"
#include "reference_cache.h"
#include "reference_renderer.h"
#include "sphere_cases.h"

namespace sss::test {
namespace {

std::vector<Rgb> at(const std::vector<Rgb>& B, const std::vector<std::size_t>& ids) {
  std::vector<Rgb> out;
  for (std::size_t i : ids) out.push_back(B[i]);
  return out;
}

// A point light 10^5 times the sphere's radius away, without attenuation, is the directional
// light along the same direction: its rays differ by 10^-5 rad across the sphere.
TEST(PointLight, FarAwayIsTheDirectionalLight) {
  const SurfelCloud sphere = make_sphere(10.0, 0.5);
  const Material milk = Material::preset("skimmilk");
  const Eigen::Vector3d d = Eigen::Vector3d(1, 1, 1).normalized();
  Light point;
  point.positional = true;
  point.position = 1e6 * d;
  point.direction = d;
  const SurfelRadiance far = render_reference(sphere, milk, {point});
  const SurfelRadiance directional = render_reference(sphere, milk, {{d, 1.0}});
  const ErrorStats e = compare_radiance(far.B, directional.B);
  std::printf("[ point light ] 10 mm skim milk sphere, a point light 1000 m away against the "
              "directional light: %s; map %d x %d\n",
              e.summary().c_str(), far.stats.map_width, far.stats.map_height);
  EXPECT_LT(e.mean, 0.001);
  EXPECT_LT(e.p99, 0.01);
}

// A marble torus (R 30 mm, tube 7 mm, 1 mm apart) lit from close by: a point light 25 mm above
// its hole with inverse-square falloff (the tube shadows its own outer side), and a spot whose
// 20 degree cone crosses the tube. Default GPU settings against the reference at 1500 points:
// the same bars as on the shared scans.
TEST(GpuPointLight, PointLightAndSpotMeetTheReference) {
  const SurfelCloud torus = make_torus(30.0, 7.0, 1.0);
  const Material marble = Material::preset("marble");
  Light point;
  point.positional = true;
  point.position = Eigen::Vector3d(0, 0, 25);
  point.direction = Eigen::Vector3d(0, 0, 1);
  point.attenuation = Eigen::Vector3d(0, 0, 1);
  point.irradiance = 625.0;  // 1 at 25 mm
  Light spot = point;
  spot.position = Eigen::Vector3d(60, 10, 40);
  spot.direction = spot.position.normalized();  // aimed at the torus's centre
  spot.cone_angle = 20.0;
  spot.exponent = 2.0;
  spot.irradiance = 5300.0;
  for (const auto& [name, light] : {std::pair{"point light", point}, std::pair{"spot", spot}}) {
    ReferenceSettings settings;
    settings.receivers = sample_of(torus, 1500, 3);
    const std::vector<Rgb> reference =
        cached_reference(SSS_TEST_REFERENCE_CACHE, torus, marble, {light}, settings).B;
    GpuScene scene(torus, marble, {light});
    const std::vector<Rgb> B = scene.render_B();
    ASSERT_EQ(B.size(), torus.size()) << name;
    std::size_t dark = 0;
    for (std::size_t i : settings.receivers)
      if (reference[i][0] + reference[i][1] + reference[i][2] == 0.0) ++dark;
    const ErrorStats e = compare_radiance(at(B, settings.receivers), at(reference, settings.receivers));
    std::printf("[ gpu point light ] marble torus, %zu points, %s: against the reference %s "
                "(%zu of %zu points unlit); map %d x %d\n",
                torus.size(), name, e.summary().c_str(), dark, settings.receivers.size(),
                scene.pass->GetLastMapWidth(), scene.pass->GetLastMapHeight());
    EXPECT_LT(e.mean, 0.005) << name;
    EXPECT_LT(e.p99, 0.05) << name;
  }
}

}  // namespace
}  // namespace sss::test
