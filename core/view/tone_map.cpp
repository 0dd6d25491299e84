#include "tone_map.h"

#include <algorithm>
#include <cmath>

namespace sss {

double srgb_encode(double linear) {
  linear = std::clamp(linear, 0.0, 1.0);
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

std::uint8_t to_srgb8(double radiance, double white) {
  const double v = white > 0.0 && std::isfinite(radiance) ? radiance / white : 0.0;
  return static_cast<std::uint8_t>(std::lround(255.0 * srgb_encode(v)));
}

}  // namespace sss
