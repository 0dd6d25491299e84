#include <gtest/gtest.h>

#include <cmath>

#include "fresnel.h"

namespace sss {
namespace {

TEST(Fresnel, NormalIncidence) {
  for (double eta : {1.0, 1.3, 1.5, 2.4}) {
    const double expected = std::pow((eta - 1) / (eta + 1), 2);
    EXPECT_NEAR(fresnel_reflectance(eta, 1.0), expected, 1e-15) << eta;
    EXPECT_NEAR(fresnel_transmittance(eta, 1.0), 1 - expected, 1e-15) << eta;
  }
}

TEST(Fresnel, GrazingReflectsEverything) {
  for (double eta : {1.3, 1.5}) {
    EXPECT_NEAR(fresnel_reflectance(eta, 0.0), 1.0, 1e-12);
    EXPECT_NEAR(fresnel_reflectance(eta, 1e-9), 1.0, 1e-6);
  }
}

TEST(Fresnel, IndexOneIsInvisible) {
  for (double c = 0.0; c <= 1.0; c += 0.05) EXPECT_NEAR(fresnel_reflectance(1.0, c), 0.0, 1e-15);
  EXPECT_NEAR(diffuse_fresnel_reflectance(1.0), 0.0016, 1e-12);
}

TEST(Fresnel, MonotoneAndBounded) {
  for (double eta : {0.7, 1.3, 1.5}) {
    double previous = fresnel_reflectance(eta, 1.0);
    for (double c = 1.0; c >= 0.0; c -= 0.01) {
      const double r = fresnel_reflectance(eta, c);
      ASSERT_GE(r, 0.0);
      ASSERT_LE(r, 1.0);
      ASSERT_GE(r, previous - 1e-15) << "eta " << eta << " cos " << c;
      previous = r;
    }
  }
}

TEST(Fresnel, TotalInternalReflectionBelowIndexOne) {
  const double eta = 0.7;  // critical angle: sin = 0.7
  EXPECT_DOUBLE_EQ(fresnel_reflectance(eta, std::cos(std::asin(0.71))), 1.0);
  EXPECT_LT(fresnel_reflectance(eta, std::cos(std::asin(0.69))), 1.0);
}

TEST(Fresnel, DiffuseReflectanceIsContinuousAtOne) {
  EXPECT_NEAR(diffuse_fresnel_reflectance(1.0 - 1e-9), diffuse_fresnel_reflectance(1.0), 2e-4);
  EXPECT_NEAR(diffuse_fresnel_reflectance(1.5), -1.44 / 2.25 + 0.71 / 1.5 + 0.668 + 0.0954, 1e-12);
}

}  // namespace
}  // namespace sss
