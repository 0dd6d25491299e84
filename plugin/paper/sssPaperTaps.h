// The paper's gather pattern: 49 taps distributed as a 2-D Gaussian over a 40 x 40 texel
// window, each weighted by the inverse of its sampling density so that the taps estimate
// the sum over the window.
#ifndef sssPaperTaps_h
#define sssPaperTaps_h

#include <array>

namespace sss
{

constexpr int kPaperTapCount = 49;
constexpr double kPaperWindowTexels = 40.0;
constexpr int kPaperMapSize = 512;

// x, y offset in texels from the centre texel; weight = texels the tap stands for.
std::array<std::array<float, 3>, kPaperTapCount> paper_taps();

}

#endif
