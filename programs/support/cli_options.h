// Command-line parsing for sss_render: every flag, its default and its unit in one table; the
// defaults of the pass's settings are the pass's own.
#pragma once

#include <cstddef>

#include <Eigen/Core>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "light_map.h"
#include "material.h"
#include "splat_coverage.h"
#include "surfel_cloud.h"

class vtkSubsurfacePass;

namespace sss::cli {

struct Options {
  std::string input;  // empty: the procedural demo shape
  std::string output_png = "sss_render.png";
  std::string linear_pfm, stats_json, bake_ply;
  std::string material = kDefaultPreset;
  bool custom_material = false;
  Rgb sigma_a{}, sigma_s{};
  double eta = kDefaultEta;
  double mm_per_unit = 1.0;  // millimetres per scene unit
  std::vector<Eigen::Vector3d> light_dirs;
  std::vector<Eigen::Vector3d> point_lights;   // positions, scene units
  Eigen::Vector3d light_attenuation{1, 0, 0};  // of point lights, as VTK's

  double light_irradiance = 1.0;
  Eigen::Vector3d view_dir{0.0, -1.0, 0.6};
  Eigen::Vector3d up{0.0, 0.0, 1.0};
  bool ortho = false;
  bool fit_all = false;  // --fit all: the camera fitted to every point (VTK's ResetCamera)
  int width = 512, height = 512;
  std::string method = "gpu";
  std::string backend = "egl";
  int gpu = -1;  // EGL device; -1: the first hardware device, else the software one;
                 // kSurfacelessPlatform: Mesa's surfaceless platform
  // The pass's settings: unset ones keep vtkSubsurfacePass's defaults.
  std::optional<std::string> quality, strategy;
  std::optional<int> grid_level, max_map_size, cell_samples;
  std::optional<double> opening_angle, group_diffusion_lengths, texel_per_radius;
  double exposure = 0.0;  // 0: automatic
  int frames = 0;
  double radius_scale = 1.0;
  double coverage_target = kDefaultCoverageTarget;  // uncovered area fraction the radius may leave
  std::string radius_mode = "automatic";  // automatic, uniform, per-point
  std::string splatting = "blended";      // blended, discs
  std::size_t mesh_samples = 0;
  std::size_t memory_cap = 0;  // bytes a load may claim; 0: the loader's default
  double isolation_ratio = 5.0;  // isolated points left out above it (isolated_points.h); 0 keeps
  bool denoise = true;  // points onto the surface they measured (denoised_surface.h)
  bool help = false;
};

// Options::gpu for Mesa's surfaceless platform instead of an EGL device (--gpu surfaceless).
constexpr int kSurfacelessPlatform = -2;

// Throws std::invalid_argument with a message naming the flag and what is wrong.
Options parse(int argc, char** argv);

// The lights the options ask for: the directional ones, then the point lights aimed at
// `centre`.
std::vector<Light> lights_of(const Options& o, const Eigen::Vector3d& centre);

// The pass's settings given on the command line, onto `pass`; the rest keep its defaults.
void apply_pass_settings(const Options& o, vtkSubsurfacePass* pass);

// The cloud's disc radii by --radius-mode, --coverage and --radius-scale (splat_coverage.h);
// returns a line saying what was chosen.
std::string apply_splat_radii(const Options& o, SurfelCloud& cloud);

// A program's arguments, flag by flag: `while (args.next())` visits each, `args.flag()` is the
// current one and `args.value()` takes the next argument as its value (std::invalid_argument
// naming the flag when there is none).
class Arguments {
 public:
  Arguments(int argc, char** argv) : argc_(argc), argv_(argv) {}
  bool next() {
    if (++i_ >= argc_) return false;
    flag_ = argv_[i_];
    return true;
  }
  const std::string& flag() const { return flag_; }
  std::string value() {
    if (i_ + 1 >= argc_) throw std::invalid_argument(flag_ + ": needs a value");
    return argv_[++i_];
  }

 private:
  int argc_;
  char** argv_;
  int i_ = 0;
  std::string flag_;
};

// The value of a numeric flag; throws std::invalid_argument naming the flag otherwise.
double number(const std::string& flag, const std::string& text);
// A whole number from 0 to hi; throws std::invalid_argument naming the flag otherwise.
std::size_t count(const std::string& flag, const std::string& text, double hi);
// `value` when it lies in [lo, hi] (a setting's range as vtkSubsurfacePass clamps it: pass
// Get...MinValue() and Get...MaxValue()); throws std::invalid_argument naming the flag otherwise.
double within(const std::string& flag, double value, double lo, double hi);
// --fit's value: true for all, false for surface.
bool fit_all(const std::string& flag, const std::string& text);
// on: true, off: false (--denoise).
bool on_off(const std::string& flag, const std::string& text);
// --isolated's value: the ratio, or 0 for keep.
double isolation_ratio(const std::string& flag, const std::string& text);
// --memory-cap's value, MiB, in bytes.
std::size_t memory_cap(const std::string& flag, const std::string& text);
// The presets' names on lines of their own, indented by `indent` and ending before column 92,
// each line after a line break.
std::string preset_list(std::size_t indent);
std::string usage();

}  // namespace sss::cli
