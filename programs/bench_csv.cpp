#include "bench_csv.h"

#include <cstdio>

namespace sss::bench {

const char* const kColumns =
    "cloud,points,material,strategy,map_size,opening_angle,cell_samples,is_paper,is_default,"
    "bake_s,light_s,frame_static_s,frame_moving_s,plain_points_s,near_field_mib,virtual_points,"
    "lit_cells,err_mean,err_p99,err_max,err8_mean,err8_max,peak_rss_mb,kind,map_s,cells_s,"
    "pyramid_s,near_s,far_s,hand_over_s,renderer";

namespace {
std::string cell(double v) {
  if (!std::isfinite(v)) return "";
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}
// A CSV field in double quotes, its quotes doubled (RFC 4180).
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}
}  // namespace

void write_row(std::ostream& out, const Row& r) {
  out << r.cloud << ',' << r.points << ',' << r.material << ',' << r.strategy << ','
      << r.map_size << ',' << cell(r.opening_angle) << ',' << cell(r.cell_samples) << ','
      << r.is_paper << ',' << r.is_default << ',' << cell(r.bake_s) << ',' << cell(r.light_s)
      << ',' << cell(r.frame_static_s) << ',' << cell(r.frame_moving_s) << ','
      << cell(r.plain_points_s) << ',' << cell(r.near_field_mib) << ','
      << cell(r.virtual_points) << ',' << cell(r.lit_cells) << ',' << cell(r.err_mean) << ','
      << cell(r.err_p99) << ',' << cell(r.err_max) << ',' << cell(r.err8_mean) << ','
      << cell(r.err8_max) << ',' << cell(r.peak_rss_mb) << ',' << r.kind << ','
      << cell(r.map_s) << ',' << cell(r.cells_s) << ',' << cell(r.pyramid_s) << ','
      << cell(r.near_s) << ',' << cell(r.far_s) << ',' << cell(r.hand_over_s) << ','
      << quoted(r.renderer) << '\n';
  out.flush();
}

}  // namespace sss::bench
