// Linear radiance to 8-bit sRGB: divide by a white level, clamp to [0, 1], sRGB transfer curve.
#pragma once

#include <cstdint>

namespace sss {

double srgb_encode(double linear);  // [0, 1] -> [0, 1]
std::uint8_t to_srgb8(double radiance, double white);

}  // namespace sss
