// The quality presets: one table that the pass, the PCL handle and the programs share.
#include <gtest/gtest.h>

#include <stdexcept>

#include "quality_settings.h"

namespace sss {
namespace {

TEST(QualitySettings, BalancedIsTheDefaultsAndEveryPresetNamesItself) {
  EXPECT_EQ(QualitySettings::preset("balanced"), QualitySettings{});
  for (const std::string& name : QualitySettings::preset_names()) {
    EXPECT_EQ(QualitySettings::preset(name).preset_name(), name);
  }
  const QualitySettings interactive = QualitySettings::preset("interactive");
  EXPECT_EQ(interactive.cell_samples, 16);
  EXPECT_EQ(interactive.max_map_size, 2048);
  EXPECT_EQ(interactive.opening_angle, 0.6);
  const QualitySettings accurate = QualitySettings::preset("accurate");
  EXPECT_EQ(accurate.cell_samples, 128);
  EXPECT_EQ(accurate.opening_angle, 0.3);
  QualitySettings custom;
  custom.cell_samples = 32;
  EXPECT_EQ(custom.preset_name(), "");
}

TEST(QualitySettings, UnknownNamesAreRefusedWithTheKnownOnes) {
  try {
    QualitySettings::preset("fastest");
    FAIL() << "an unknown preset was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("interactive, balanced or accurate"), std::string::npos);
  }
  KernelStrategy s = KernelStrategy::NearFar;
  EXPECT_TRUE(strategy_from_name("paper", s));
  EXPECT_EQ(s, KernelStrategy::Paper);
  EXPECT_FALSE(strategy_from_name("foo", s));
  EXPECT_EQ(s, KernelStrategy::Paper);
  EXPECT_STREQ(strategy_name(KernelStrategy::NearFar), "near-far");
}

}  // namespace
}  // namespace sss
