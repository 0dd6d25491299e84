// The one error metric of the project, for images and per-point radiance.
//
// Over the samples (pixels or points) present in both: a sample's relative error is the mean
// over RGB of |test - reference| divided by the mean over RGB of the reference. Samples whose
// reference mean is below 1 % of the largest one are left out (they are too dark for a relative
// error to mean anything). Reported: mean, 99th percentile and max of that relative error, and
// the mean and max difference of 8-bit sRGB values over all channels, both tone-mapped with
// white = the reference's largest channel value.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "material.h"

namespace sss {

struct ErrorStats {
  std::size_t compared = 0;      // samples in the relative error
  std::size_t excluded_dark = 0;  // present in both, below 1 % of the brightest
  double mean = 0, p99 = 0, max = 0;  // relative (0.01 = 1 %)
  double srgb8_mean = 0, srgb8_max = 0;
  std::string summary() const;
};

// `present`: empty, or one flag per sample (non-zero where both inputs have a value).
// Throws std::invalid_argument for sizes that differ.
ErrorStats compare_radiance(const std::vector<Rgb>& test, const std::vector<Rgb>& reference,
                            const std::vector<std::uint8_t>& present = {});

}  // namespace sss
