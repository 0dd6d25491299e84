#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "material.h"

namespace sss {
namespace {

std::string refusal(const Material& m) {
  try {
    m.validate();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(Material, TwelvePresets) {
  EXPECT_EQ(Material::preset_names().size(), 12u);
  const Material marble = Material::preset("marble", 1.5, 1000);
  EXPECT_DOUBLE_EQ(marble.sigma_s_prime[0], 2.19);
  EXPECT_DOUBLE_EQ(marble.sigma_a[2], 0.0071);
  EXPECT_DOUBLE_EQ(marble.eta[1], 1.5);
  EXPECT_DOUBLE_EQ(marble.mm_per_unit, 1000);
  for (const auto& name : Material::preset_names()) EXPECT_NO_THROW(Material::preset(name));
}

TEST(Material, UnknownPresetListsTheKnownOnes) {
  try {
    Material::preset("granite");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("granite"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("marble"), std::string::npos);
  }
}

TEST(Material, InvalidValuesAreNamed) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Material m = Material::preset("marble");
  m.sigma_a[1] = -0.1;
  EXPECT_NE(refusal(m).find("sigma_a green"), std::string::npos) << refusal(m);
  m = Material::preset("marble");
  m.sigma_s_prime[2] = nan;
  EXPECT_NE(refusal(m).find("sigma_s' blue"), std::string::npos) << refusal(m);
  m = Material::preset("marble");
  m.eta[0] = 0.0;
  EXPECT_NE(refusal(m).find("eta red"), std::string::npos) << refusal(m);
  m = Material::custom({0.1, 0.1, 0.1}, {1, 1, 1}, 1.3);
  m.sigma_a[0] = 0.0;
  m.sigma_s_prime[0] = 0.0;
  EXPECT_NE(refusal(m).find("sigma_t' red"), std::string::npos) << refusal(m);
  m = Material::preset("marble");
  m.mm_per_unit = -1;
  EXPECT_NE(refusal(m).find("mm_per_unit"), std::string::npos) << refusal(m);
  EXPECT_THROW(Material::custom({0, 0, 0}, {1, 1, 1}, std::numeric_limits<double>::infinity()),
               std::invalid_argument);
}

}  // namespace
}  // namespace sss
