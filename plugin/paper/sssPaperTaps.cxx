#include "sssPaperTaps.h"

#include <cmath>

namespace sss
{

std::array<std::array<float, 3>, kPaperTapCount> paper_taps()
{
  // Deterministic stratified samples of a Gaussian (sigma = a quarter of the window) truncated
  // to the disc inscribed in the window: radius by the inverse of the truncated Rayleigh CDF,
  // angle by the golden angle.
  const double sigma = kPaperWindowTexels / 4.0;
  const double reach = kPaperWindowTexels / 2.0;
  const double kept = 1.0 - std::exp(-reach * reach / (2.0 * sigma * sigma));
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  std::array<std::array<float, 3>, kPaperTapCount> taps{};
  for (int k = 0; k < kPaperTapCount; ++k)
  {
    const double u = (k + 0.5) / kPaperTapCount;
    const double r = sigma * std::sqrt(-2.0 * std::log(1.0 - u * kept));
    const double density =
      std::exp(-r * r / (2.0 * sigma * sigma)) / (2.0 * M_PI * sigma * sigma * kept);
    taps[k] = { { static_cast<float>(r * std::cos(golden * k)),
      static_cast<float>(r * std::sin(golden * k)),
      static_cast<float>(1.0 / (kPaperTapCount * density)) } };
  }
  return taps;
}

}
