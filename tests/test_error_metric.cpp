#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "error_metric.h"
#include "linear_image.h"

namespace sss {
namespace {

TEST(ErrorMetric, IdenticalIsZero) {
  const std::vector<Rgb> a{{1, 2, 3}, {0.5, 0.5, 0.5}};
  const ErrorStats s = compare_radiance(a, a);
  EXPECT_EQ(s.compared, 2u);
  EXPECT_EQ(s.mean, 0.0);
  EXPECT_EQ(s.max, 0.0);
  EXPECT_EQ(s.srgb8_max, 0.0);
}

TEST(ErrorMetric, RelativeErrorIsMeanOverRgbOverMeanReference) {
  const std::vector<Rgb> ref{{1, 1, 1}, {2, 0, 1}};
  const std::vector<Rgb> test{{1.03, 0.97, 1}, {2.2, 0.1, 1}};
  const ErrorStats s = compare_radiance(test, ref);
  EXPECT_NEAR(s.mean, 0.5 * (0.02 + 0.1), 1e-12);  // (0.06/3)/1 and (0.3/3)/1
  EXPECT_NEAR(s.max, 0.1, 1e-12);
}

TEST(ErrorMetric, DarkSamplesAreLeftOutAndNaNNeverMatches) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Rgb> ref{{1, 1, 1}, {0.001, 0.001, 0.001}, {1, 1, 1}};
  const std::vector<Rgb> test{{1, 1, 1}, {0.5, 0.5, 0.5}, {nan, 1, 1}};
  const ErrorStats s = compare_radiance(test, ref);
  EXPECT_EQ(s.excluded_dark, 1u);
  EXPECT_EQ(s.compared, 2u);
  EXPECT_TRUE(std::isinf(s.max));
}

TEST(ErrorMetric, CoverageMaskAndPercentile) {
  std::vector<Rgb> ref(200, Rgb{1, 1, 1}), test = ref;
  test[7] = {2, 2, 2};  // 1 of 200 is 100 % off: above the 99th percentile
  std::vector<std::uint8_t> present(200, 1);
  EXPECT_NEAR(compare_radiance(test, ref, present).p99, 0.0, 1e-15);
  test[8] = test[9] = {2, 2, 2};
  EXPECT_NEAR(compare_radiance(test, ref, present).p99, 1.0, 1e-15);
  present[7] = present[8] = present[9] = 0;
  EXPECT_EQ(compare_radiance(test, ref, present).max, 0.0);
  EXPECT_THROW(compare_radiance(test, {}, {}), std::invalid_argument);
}

TEST(ErrorMetric, ImagesCompareOnPixelsCoveredInBoth) {
  LinearImage a(2, 1), b(2, 1);
  a.at(0, 0) = b.at(0, 0) = {1, 1, 1};
  a.covered = {1, 1};
  b.covered = {1, 0};
  a.at(1, 0) = {5, 5, 5};
  EXPECT_EQ(compare_images(a, b).compared, 1u);
  EXPECT_EQ(compare_images(a, b).max, 0.0);
  EXPECT_THROW(compare_images(a, LinearImage(3, 1)), std::invalid_argument);
}

TEST(LinearImage, PfmRoundTrip) {
  LinearImage image(3, 2);
  image.at(2, 1) = {0.25, 1.5, 3.0};
  image.covered[5] = 1;
  const std::string path = ::testing::TempDir() + "/roundtrip.pfm";
  write_pfm(image, path);
  const LinearImage back = read_pfm(path);
  EXPECT_EQ(back.width, 3);
  EXPECT_EQ(back.height, 2);
  EXPECT_EQ(back.at(2, 1)[1], 1.5f);
  EXPECT_EQ(back.at(0, 0)[0], 0.0f);
  EXPECT_THROW(write_pfm(image, "/nonexistent-folder/x.pfm"), std::runtime_error);
}

}  // namespace
}  // namespace sss
