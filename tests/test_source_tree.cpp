// The tree's far-field expansion against the plain sum over every source, and over the sources
// beyond a distance.
#include <gtest/gtest.h>

#include "procedural_shapes.h"
#include "reference_renderer.h"

namespace sss {
namespace {

TEST(SourceTree, ExpansionAgreesWithDirectSum) {
  const SurfelCloud sphere = make_sphere(10.0, 0.5);  // mm
  const Material material = Material::preset("skimmilk");  // a long kernel: most is far field
  const std::vector<Light> light{{Eigen::Vector3d(1, 1, 2), 1.0}};
  ReferenceSettings direct;
  direct.tree.theta = 0.0;
  direct.receivers = {0};
  ReferenceSettings fast_settings;
  fast_settings.receivers = {0};
  const ReferenceSolver exact(sphere, material, light, direct);
  const ReferenceSolver fast(sphere, material, light, fast_settings);
  double worst = 0.0, sum = 0.0;
  int count = 0;
  for (std::size_t i = 0; i < sphere.size(); i += 97) {
    const Rgb a = exact.sources_B_at(sphere.positions[i]);
    const Rgb b = fast.sources_B_at(sphere.positions[i]);
    for (int c = 0; c < 3; ++c) {
      const double e = std::fabs(b[c] / a[c] - 1);
      worst = std::max(worst, e);
      sum += e;
      ++count;
    }
  }
  std::printf("[ tree ] default theta vs direct sum: mean %.2e, worst %.2e relative\n",
              sum / count, worst);
  // The reference's own error must stay well below the 0.5 % it is used to judge.
  EXPECT_LT(sum / count, 5e-4);
  EXPECT_LT(worst, 3e-3);
}

// The far field's sum leaves out the cells nearer than a distance (the near field's table
// holds them): from the tree it must agree with the plain sum over the same cells, and grow
// to the whole as the distance shrinks.
TEST(SourceTree, BeyondADistanceAgreesWithDirectSum) {
  const SurfelCloud torus = make_torus(20.0, 6.0, 0.5);
  const Material material = Material::preset("marble");
  ReferenceSettings one, direct;
  one.receivers = direct.receivers = {0};
  direct.tree.theta = 0.0;
  const std::vector<Light> light{{Eigen::Vector3d(0, 1, 1), 1.0}};
  const ReferenceSolver fast(torus, material, light, one), exact(torus, material, light, direct);
  int fewer = 0;  // points with lit cells within the distance
  for (std::size_t i = 0; i < torus.size(); i += 211) {
    const Rgb all = fast.sources_B_at(torus.positions[i]);
    const Rgb beyond = fast.sources_B_at(torus.positions[i], 2.0);
    const Rgb beyond_exact = exact.sources_B_at(torus.positions[i], 2.0);
    const Rgb none = fast.sources_B_at(torus.positions[i], 1e6);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(beyond[c], beyond_exact[c], 3e-3 * beyond_exact[c]);
      EXPECT_LE(beyond[c], all[c]);
      EXPECT_EQ(none[c], 0.0);
    }
    if (beyond[0] < all[0]) ++fewer;
  }
  EXPECT_GT(fewer, 10);
}

}  // namespace
}  // namespace sss
