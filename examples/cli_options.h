// Command-line parsing for sss_render: every flag, its default and its unit in one table.
#pragma once

#include <cstddef>

#include <Eigen/Core>
#include <string>
#include <vector>

#include "material.h"

namespace sss::cli {

struct Options {
  std::string input;  // empty: the procedural demo shape
  std::string output_png = "sss_render.png";
  std::string linear_pfm, stats_json, bake_ply;
  std::string material = "marble";
  bool custom_material = false;
  Rgb sigma_a{}, sigma_s{};
  double eta = 1.3;
  double scale = 1.0;  // mm per scene unit
  std::vector<Eigen::Vector3d> light_dirs;
  double light_irradiance = 1.0;
  Eigen::Vector3d view_dir{0.0, -1.0, 0.6};
  Eigen::Vector3d up{0.0, 0.0, 1.0};
  bool ortho = false;
  int width = 512, height = 512;
  std::string method = "grid";
  std::string backend = "egl";
  std::string strategy = "grid";  // the pass's defaults
  int grid_level = 0;
  int max_map_size = 512;
  double opening_angle = 2.0;
  double group_diffusion_lengths = 1000.0;
  double exposure = 0.0;  // 0: automatic
  double texel_per_z_r = 0.25;
  int frames = 0;
  double radius_scale = 1.5;
  std::size_t mesh_samples = 0;
  bool help = false;
};

// Throws std::invalid_argument with a message naming the flag and what is wrong.
Options parse(int argc, char** argv);

// The value of a numeric flag; throws std::invalid_argument naming the flag otherwise.
double number(const std::string& flag, const std::string& text);
std::string usage();

}  // namespace sss::cli
