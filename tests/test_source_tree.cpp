// The tree's far-field expansion against the plain sum over every sample, and the split of the
// kernel into near and far parts.
#include <gtest/gtest.h>

#include "procedural_shapes.h"
#include "reference_renderer.h"

namespace sss {
namespace {

TEST(SourceTree, ExpansionAgreesWithDirectSum) {
  const SurfelCloud sphere = make_sphere(10.0, 0.5);  // mm
  const Material material = Material::preset("skimmilk");  // a long kernel: most is far field
  const std::vector<DirectionalLight> light{{Eigen::Vector3d(1, 1, 2), 1.0}};
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
    const Rgb a = exact.sources_B_at(sphere.positions[i], KernelWindow::all());
    const Rgb b = fast.sources_B_at(sphere.positions[i], KernelWindow::all());
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

TEST(SourceTree, NearAndFarPartsAddUpToTheWhole) {
  const SurfelCloud torus = make_torus(20.0, 6.0, 0.5);
  const Material material = Material::preset("marble");
  ReferenceSettings one;
  one.receivers = {0};
  const ReferenceSolver solver(torus, material, {{Eigen::Vector3d(0, 1, 1), 1.0}}, one);
  for (std::size_t i = 0; i < torus.size(); i += 211) {
    const Rgb all = solver.sources_B_at(torus.positions[i], KernelWindow::all());
    const Rgb near = solver.sources_B_at(torus.positions[i], KernelWindow::near(2.0, 4.0));
    const Rgb far = solver.sources_B_at(torus.positions[i], KernelWindow::far(2.0, 4.0));
    // Each side is summed with the tree's own accuracy (see the test above).
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(near[c] + far[c], all[c], 3e-3 * all[c]);
  }
}

TEST(KernelWindow, WeightsAreComplementaryAndSmooth) {
  const KernelWindow near = KernelWindow::near(1.0, 2.0), far = KernelWindow::far(1.0, 2.0);
  for (double r = 0.0; r < 3.0; r += 0.01) EXPECT_DOUBLE_EQ(near.weight(r) + far.weight(r), 1.0);
  EXPECT_EQ(far.weight(1.0), 0.0);
  EXPECT_EQ(far.weight(2.0), 1.0);
  EXPECT_NEAR(far.weight(1.5), 0.5, 1e-15);
}

}  // namespace
}  // namespace sss
