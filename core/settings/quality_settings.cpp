#include "quality_settings.h"

#include <stdexcept>

namespace sss {

const char* strategy_name(KernelStrategy strategy) {
  return strategy == KernelStrategy::Paper ? "paper" : "near-far";
}

bool strategy_from_name(const std::string& name, KernelStrategy& strategy) {
  for (KernelStrategy s : {KernelStrategy::Paper, KernelStrategy::NearFar}) {
    if (name == strategy_name(s)) {
      strategy = s;
      return true;
    }
  }
  return false;
}

bool QualitySettings::operator==(const QualitySettings& o) const {
  return strategy == o.strategy && texel_per_radius == o.texel_per_radius &&
         max_map_size == o.max_map_size && cell_samples == o.cell_samples &&
         opening_angle == o.opening_angle &&
         max_group_diffusion_lengths == o.max_group_diffusion_lengths &&
         grid_level == o.grid_level;
}

const std::vector<std::string>& QualitySettings::preset_names() {
  static const std::vector<std::string> names{"interactive", "balanced", "accurate"};
  return names;
}

QualitySettings QualitySettings::preset(const std::string& name) {
  QualitySettings s;
  if (name == "interactive") {
    s.cell_samples = 16;
    s.max_map_size = 2048;
    s.opening_angle = 0.6;
  } else if (name == "accurate") {
    s.cell_samples = 128;
    s.opening_angle = 0.3;
  } else if (name != "balanced") {
    throw std::invalid_argument("'" + name +
                                "' is not a quality preset: use interactive, balanced or accurate");
  }
  return s;
}

std::string QualitySettings::preset_name() const {
  for (const std::string& name : preset_names()) {
    if (preset(name) == *this) return name;
  }
  return "";
}

}  // namespace sss
