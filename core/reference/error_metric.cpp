#include "error_metric.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <stdexcept>

#include "tone_map.h"

namespace sss {

std::string ErrorStats::summary() const {
  char text[256];
  std::snprintf(text, sizeof text,
                "relative error mean %.3f %%, p99 %.3f %%, max %.3f %% over %zu samples "
                "(%zu dark left out); 8-bit sRGB difference mean %.2f, max %.0f",
                100 * mean, 100 * p99, 100 * max, compared, excluded_dark, srgb8_mean, srgb8_max);
  return text;
}

ErrorStats compare_radiance(const std::vector<Rgb>& test, const std::vector<Rgb>& reference,
                            const std::vector<std::uint8_t>& present) {
  if (test.size() != reference.size() || (!present.empty() && present.size() != test.size()))
    throw std::invalid_argument("[sss::compare_radiance] inputs differ in size");
  auto in_both = [&](std::size_t i) { return present.empty() || present[i] != 0; };
  auto level = [](const Rgb& v) { return (v[0] + v[1] + v[2]) / 3.0; };
  double brightest = 0.0, white = 0.0;
  for (std::size_t i = 0; i < reference.size(); ++i) {
    if (!in_both(i)) continue;
    brightest = std::max(brightest, level(reference[i]));
    for (double v : reference[i]) white = std::max(white, v);
  }
  ErrorStats stats;
  std::vector<double> relative;
  double srgb_sum = 0.0;
  std::size_t srgb_count = 0;
  for (std::size_t i = 0; i < reference.size(); ++i) {
    if (!in_both(i)) continue;
    for (int c = 0; c < 3; ++c) {
      const double d = std::abs(int(to_srgb8(test[i][c], white)) - int(to_srgb8(reference[i][c], white)));
      srgb_sum += d;
      stats.srgb8_max = std::max(stats.srgb8_max, d);
      ++srgb_count;
    }
    const double ref = level(reference[i]);
    if (!(ref >= 0.01 * brightest) || !(ref > 0.0)) {
      ++stats.excluded_dark;
      continue;
    }
    const double diff = (std::fabs(test[i][0] - reference[i][0]) +
                         std::fabs(test[i][1] - reference[i][1]) +
                         std::fabs(test[i][2] - reference[i][2])) / 3.0;
    // A NaN in the test counts as an infinite error, never as a match.
    relative.push_back(std::isfinite(diff) ? diff / ref : std::numeric_limits<double>::infinity());
  }
  stats.compared = relative.size();
  if (srgb_count > 0) stats.srgb8_mean = srgb_sum / srgb_count;
  if (relative.empty()) return stats;
  double sum = 0.0;
  for (double r : relative) sum += r;
  stats.mean = sum / relative.size();
  stats.max = *std::max_element(relative.begin(), relative.end());
  const std::size_t k = std::min(relative.size() - 1,
                                 static_cast<std::size_t>(std::ceil(0.99 * relative.size())) - 1);
  std::nth_element(relative.begin(), relative.begin() + k, relative.end());
  stats.p99 = relative[k];
  return stats;
}

}  // namespace sss
