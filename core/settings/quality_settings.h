// How finely the real-time method sums B, in one place: the defaults (the "balanced" preset)
// and the named presets that vtkSubsurfacePass, the PCL handle, sss_render, sss_view and
// sss_bench share. Costs and errors of each preset: docs/benchmark/bench.md.
#pragma once

#include <string>
#include <vector>

namespace sss {

enum class KernelStrategy {
  Paper = 0,   // the 2005 paper: 512 map, 49 Gaussian taps in a 40 x 40 window at 64^3 points
  NearFar = 1  // each surfel's cell lit; near field by a table, far field by a walk
};

// "paper" or "near-far".
const char* strategy_name(KernelStrategy strategy);
// False for a name that is neither.
bool strategy_from_name(const std::string& name, KernelStrategy& strategy);

struct QualitySettings {
  KernelStrategy strategy = KernelStrategy::NearFar;
  double texel_per_radius = 0.0625;          // light-map texel over the disc radius
  int max_map_size = 4096;                   // light-map texels a side, at most
  int cell_samples = 64;                     // per cell and light (8 x where an edge crosses)
  double opening_angle = 0.4;                // far field: a group's spread over its distance
  double max_group_diffusion_lengths = 4.0;  // far field: a group's radius, in 1/s_tr
  int grid_level = 0;                        // paper: 2^level grid points a side, 0: its 64

  bool operator==(const QualitySettings& o) const;
  bool operator!=(const QualitySettings& o) const { return !(*this == o); }

  // "interactive", "balanced" (the defaults above) or "accurate"; std::invalid_argument
  // naming the presets for any other name.
  static QualitySettings preset(const std::string& name);
  static const std::vector<std::string>& preset_names();
  // The preset these settings equal, or "" when none does.
  std::string preset_name() const;
};

}  // namespace sss
