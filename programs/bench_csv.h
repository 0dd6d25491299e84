// sss_bench's output: one row of bench.csv per measurement (its columns are the ones
// scripts/bench_report.py reads); a value not measured is NaN, an empty cell.
#pragma once

#include <cmath>
#include <cstddef>
#include <ostream>
#include <string>

namespace sss::bench {

struct Row {
  std::string cloud, material, strategy, kind = "sweep";
  std::string renderer;  // the OpenGL renderer and context that drew it
  std::size_t points = 0;
  int map_size = 0;
  double opening_angle = NAN, cell_samples = NAN;
  bool is_paper = false, is_default = false;
  double bake_s = NAN, light_s = NAN, frame_static_s = NAN, frame_moving_s = NAN,
         plain_points_s = NAN;
  // light_s by step (near-far): light map, cells' light, upward pass, near field, far field,
  // hand-over of B to the view.
  double map_s = NAN, cells_s = NAN, pyramid_s = NAN, near_s = NAN, far_s = NAN,
         hand_over_s = NAN;
  double near_field_mib = NAN, virtual_points = NAN, lit_cells = NAN;
  double err_mean = NAN, err_p99 = NAN, err_max = NAN, err8_mean = NAN, err8_max = NAN;
  double peak_rss_mb = NAN;
};

// The header line's columns.
extern const char* const kColumns;

// One line, flushed.
void write_row(std::ostream& out, const Row& r);

}  // namespace sss::bench
