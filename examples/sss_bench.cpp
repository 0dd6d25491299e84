// sss_bench: speed against error. For each cloud and material it renders a sweep of settings
// (kernel strategy, virtual-grid level, illumination-map size; the 2005 paper's setting is one
// row) and measures, in one run and one window: frame time with the light static and moving,
// the bake (steps 1-2), virtual points kept, lit samples, and the per-point error against the
// CPU reference (cached on disk); plain VTK points of the same cloud are the baseline. A scale
// sweep renders the mesh sampled to N points. Writes CSV, then bench_report.py writes the
// Markdown table and the plots.
#include <vtkFloatArray.h>
#include <vtkRenderWindow.h>

#include <sys/resource.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli_options.h"
#include "cloud_input.h"
#include "error_metric.h"
#include "procedural_shapes.h"
#include "reference_cache.h"
#include "render_window.h"
#include "scan_io.h"
#include "stopwatch.h"
#include "translucent_scene.h"

namespace {

namespace fs = std::filesystem;
using sss::cli::number;
using sss::cli::TranslucentScene;

const char* kUsage = R"(usage: sss_bench [CLOUD.pcd|.ply|.ply.gz ...] [options]

Speed against error of the real-time path, in one run: a sweep of settings per cloud and
material, plain VTK points as the baseline, the CPU reference per point (cached), and a scale
sweep. Writes OUT/bench.csv, then OUT/bench.md, OUT/bench_tradeoff.png and OUT/bench_scale.png
(scripts/bench_report.py, Debian's python3-matplotlib).

Without CLOUD: the shared dragon (dragon_vrip_res2.ply.gz) sampled to 640,826 points, the
paper's dragon size, and the shared Stanford bunny's vertices, both 1000 mm per unit.

options (default in brackets)
  --quick              a procedural torus of 8,300 points, marble and ketchup, four
                       settings, a scale sweep of 2,000-8,000 points: about a minute (the
                       test suite runs it to keep the benchmark working)
  --materials LIST     comma-separated presets [marble,skimmilk,ketchup]
  --mm-per-unit F      for given clouds [1]
  --samples N          for given PLY meshes: N points sampled on the surface [0: vertices]
  --scale-mesh FILE    mesh the scale sweep samples [the shared dragon]
  --scale-points LIST  point counts of the scale sweep [100000,300000,1000000,2000000,5000000]
  --scale-strategies L strategies the scale sweep times: paper (the paper's setting), grid
                       (the pass's defaults), surfel or grid-near (the accurate setting)
                       [paper,grid,surfel]
  --settings LIST      measure these settings instead of the sweep: comma-separated
                       strategy[:map[:level[:angle[:groups]]]] (strategy paper, grid,
                       grid-near or surfel; max map side; grid level, 0 automatic; opening
                       angle; largest group in diffusion lengths), e.g. surfel:1024:0:0.8:4
  --frames N           frames per timing (a light-moving timing with bakes over 2 s uses 1)
                       [8]
  --size N             window N x N pixels [512]
  --max-bake-s S       once a setting's bake exceeds S seconds, the costlier settings of
                       that strategy (finer grid, larger map, more points) are skipped [300]
  --out DIR            output folder [bench]
  --cache DIR          reference cache folder [$XDG_CACHE_HOME/sss, else ~/.cache/sss]
  --help               this text
)";

struct Options {
  std::vector<std::string> clouds;
  bool quick = false;
  std::vector<std::string> materials{"marble", "skimmilk", "ketchup"};
  double mm_per_unit = 1.0;
  std::size_t samples = 0;
  std::string scale_mesh;
  std::vector<std::size_t> scale_points{100000, 300000, 1000000, 2000000, 5000000};
  std::vector<std::string> scale_strategies{"paper", "near-far"};
  std::vector<std::string> settings;  // replaces the sweep when given
  int frames = 8;
  int size = 512;
  double max_bake_s = 300.0;
  fs::path out = "bench";
  fs::path cache;
};

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, ',');)
    if (!part.empty()) parts.push_back(part);
  return parts;
}


// A setting of the pass; unset fields keep the pass's defaults.
struct Setting {
  std::string strategy;
  int max_map = 0, cell_samples = 0;
  double opening_angle = 0;
  bool is_paper = false, is_default = false;
};

// "strategy[:map[:angle[:samples]]]", e.g. "near-far:1024:1:8"; "paper" is the paper's.
Setting setting_of(const std::string& text) {
  std::vector<std::string> f;
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, ':');) f.push_back(part);
  Setting s;
  s.strategy = f.at(0);
  vtkNew<vtkSubsurfacePass> pass;
  if (!pass->SetKernelStrategyByName(s.strategy))
    throw std::invalid_argument("--settings: '" + s.strategy + "' is not near-far or paper");
  if (f.size() > 1) s.max_map = static_cast<int>(number("--settings", f[1]));
  if (f.size() > 2) s.opening_angle = number("--settings", f[2]);
  if (f.size() > 3) s.cell_samples = static_cast<int>(number("--settings", f[3]));
  s.is_paper = s.strategy == "paper";
  vtkNew<vtkSubsurfacePass> defaults;
  s.is_default = !s.is_paper && (s.max_map == 0 || s.max_map == defaults->GetMaxMapSize()) &&
                 (s.opening_angle == 0 || s.opening_angle == defaults->GetOpeningAngle()) &&
                 (s.cell_samples == 0 || s.cell_samples == defaults->GetCellSamples());
  return s;
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(flag + ": needs a value");
      return argv[++i];
    };
    if (flag == "--help") {
      std::fputs(kUsage, stdout);
      std::exit(0);
    } else if (flag == "--quick") {
      o.quick = true;
    } else if (flag == "--materials") {
      o.materials = split(value());
    } else if (flag == "--mm-per-unit") {
      o.mm_per_unit = number(flag, value());
    } else if (flag == "--samples") {
      o.samples = static_cast<std::size_t>(number(flag, value()));
    } else if (flag == "--scale-mesh") {
      o.scale_mesh = value();
    } else if (flag == "--scale-points") {
      o.scale_points.clear();
      for (const std::string& n : split(value()))
        o.scale_points.push_back(static_cast<std::size_t>(number(flag, n)));
    } else if (flag == "--scale-strategies") {
      o.scale_strategies = split(value());
    } else if (flag == "--settings") {
      o.settings = split(value());
      for (const std::string& text : o.settings) setting_of(text);
    } else if (flag == "--frames") {
      o.frames = static_cast<int>(number(flag, value()));
    } else if (flag == "--size") {
      o.size = static_cast<int>(number(flag, value()));
    } else if (flag == "--max-bake-s") {
      o.max_bake_s = number(flag, value());
    } else if (flag == "--out") {
      o.out = value();
    } else if (flag == "--cache") {
      o.cache = value();
    } else if (!flag.empty() && flag[0] == '-') {
      throw std::invalid_argument(flag + ": unknown option (see --help)");
    } else {
      o.clouds.push_back(flag);
    }
  }
  if (o.frames < 1 || o.size < 16 || !(o.mm_per_unit > 0) || o.materials.empty())
    throw std::invalid_argument("--frames, --size, --mm-per-unit need positive values and "
                                "--materials at least one name");
  for (const std::string& s : o.scale_strategies) setting_of(s);
  if (o.cache.empty()) {
    const char* xdg = std::getenv("XDG_CACHE_HOME");
    const char* home = std::getenv("HOME");
    o.cache = xdg && *xdg ? fs::path(xdg) / "sss"
              : home && *home ? fs::path(home) / ".cache" / "sss"
                              : o.out / "reference-cache";
  }
  return o;
}

// One row of bench.csv (columns: scripts/bench_report.py); NaN is an empty cell.
struct Row {
  std::string cloud, material, strategy, kind = "sweep";
  std::size_t points = 0;
  int grid_level = 0, map_size = 0;
  double opening_angle = 0, group_lengths = 0;
  bool is_paper = false, is_default = false;
  double bake_s = NAN, frame_static_s = NAN, frame_moving_s = NAN, plain_points_s = NAN;
  double virtual_points = NAN, lit_samples = NAN;
  double err_mean = NAN, err_p99 = NAN, err_max = NAN, err8_mean = NAN, err8_max = NAN;
  double peak_rss_mb = NAN;
};

const char* kColumns =
  "cloud,points,material,strategy,grid_level,map_size,opening_angle,group_lengths,is_paper,"
  "is_default,bake_s,frame_static_s,frame_moving_s,plain_points_s,virtual_points,lit_samples,"
  "err_mean,err_p99,err_max,err8_mean,err8_max,peak_rss_mb,kind";

std::string cell(double v) {
  if (!std::isfinite(v)) return "";
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

void write_row(std::ostream& out, const Row& r) {
  out << r.cloud << ',' << r.points << ',' << r.material << ',' << r.strategy << ','
      << r.grid_level << ',' << r.map_size << ',' << r.opening_angle << ',' << r.group_lengths
      << ',' << r.is_paper << ',' << r.is_default << ',' << cell(r.bake_s) << ','
      << cell(r.frame_static_s) << ',' << cell(r.frame_moving_s) << ','
      << cell(r.plain_points_s) << ',' << cell(r.virtual_points) << ',' << cell(r.lit_samples)
      << ',' << cell(r.err_mean) << ',' << cell(r.err_p99) << ',' << cell(r.err_max) << ','
      << cell(r.err8_mean) << ',' << cell(r.err8_max) << ',' << cell(r.peak_rss_mb) << ','
      << r.kind << '\n';
  out.flush();
}

// The sweep: the paper's setting, the pass's defaults (the PCL handle's interactive quality),
// the grid strategies by level, the per-surfel walk by map size, and the handle's balanced and
// accurate qualities.
std::vector<Setting> sweep(bool quick) {
  const Setting paper = setting_of("paper"), defaults = setting_of("near-far");
  if (quick) return {paper, defaults, setting_of("near-far:1024:1:8")};
  return {paper, defaults, setting_of("near-far:1024:1:8"), setting_of("near-far:2048:1:16"),
          setting_of("near-far:4096:0.3:32")};
}

struct Cloud {
  std::string name;
  sss::SurfelCloud surfels;
  double mm_per_unit;
};

// Peak resident memory since the last reset, MiB (Linux: /proc/self/status VmHWM).
double peak_rss_mb() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  return NAN;
}

void reset_peak_rss() { std::ofstream("/proc/self/clear_refs") << "5"; }

constexpr double kQuickSpacing = 1.0;  // mm: the quick mode's torus has about 8,300 points

const std::vector<sss::DirectionalLight> kLights{{Eigen::Vector3d(-0.3, 0.5, 0.8).normalized(), 1.0}};

// The reference's progress in steps of 10 %, one line each (logs stay readable).
void print_progress(std::size_t done, std::size_t total) {
  static std::size_t shown = 0;
  const std::size_t tenth = total ? 10 * done / total : 10;
  if (done == 0 || tenth < shown) shown = 0;
  if (tenth > shown || done == total) {
    shown = tenth;
    std::fprintf(stderr, "  reference: %3zu %% (%zu of %zu points)\n", 10 * tenth, done, total);
  }
}

std::vector<sss::Rgb> read_B(TranslucentScene& scene) {
  vtkNew<vtkFloatArray> B;
  if (!scene.pass->GetSurfelRadiance(scene.actor, B))
    throw std::runtime_error("the pass computed no radiance (see the errors above)");
  std::vector<sss::Rgb> out(static_cast<std::size_t>(B->GetNumberOfTuples()));
  for (std::size_t i = 0; i < out.size(); ++i)
    for (int c = 0; c < 3; ++c) out[i][c] = B->GetValue(static_cast<vtkIdType>(3 * i + c));
  return out;
}

// Applies a setting, renders the bake, times frames; fills the row's timings and counts.
void measure(TranslucentScene& scene, const Setting& s, int frames, Row& row) {
  vtkSubsurfacePass* pass = scene.pass;
  vtkNew<vtkSubsurfacePass> defaults;
  pass->SetKernelStrategyByName(s.strategy);
  pass->SetMaxMapSize(s.max_map ? s.max_map : defaults->GetMaxMapSize());
  pass->SetOpeningAngle(s.opening_angle ? s.opening_angle : defaults->GetOpeningAngle());
  pass->SetCellSamples(s.cell_samples ? s.cell_samples : defaults->GetCellSamples());
  scene.window->Render();
  row.strategy = s.strategy;
  row.is_paper = s.is_paper;
  row.is_default = s.is_default;
  row.map_size = s.is_paper ? 512 : pass->GetMaxMapSize();
  row.grid_level = pass->GetLastGridLevel();
  row.opening_angle = pass->GetOpeningAngle();
  row.group_lengths = pass->GetCellSamples();
  row.bake_s = pass->GetLastBakeSeconds() + pass->GetLastIlluminationSeconds() +
               pass->GetLastSurfelSeconds();
  row.virtual_points = static_cast<double>(pass->GetLastVirtualPoints());
  row.lit_samples = static_cast<double>(pass->GetLastLitCells());
  row.frame_static_s = sss::cli::time_light_static(scene, frames);
  row.frame_moving_s = sss::cli::time_light_moving(scene, row.bake_s > 2.0 ? 1 : frames);
}

void print_row(const Row& r) {
  std::fprintf(stderr,
               "  %-9s level %d map %4d angle %.2g groups %g: bake %8.3f s, static %.4f s (%.2fx), moving %8.3f s "
               "(%.1fx), error mean %.3f %% p99 %.2f %% max %.1f %%\n",
               r.strategy.c_str(), r.grid_level, r.map_size, r.opening_angle, r.group_lengths, r.bake_s, r.frame_static_s,
               r.frame_static_s / r.plain_points_s, r.frame_moving_s,
               r.frame_moving_s / r.plain_points_s, 100 * r.err_mean, 100 * r.err_p99,
               100 * r.err_max);
}

void run_sweep(const Options& o, const Cloud& cloud, std::ostream& csv) {
  std::fprintf(stderr, "%s: %zu surfels\n", cloud.name.c_str(), cloud.surfels.size());
  auto window = sss::cli::make_render_window("egl", o.size, o.size);
  TranslucentScene scene(window, cloud.surfels,
                         sss::Material::preset(o.materials[0], 1.3, cloud.mm_per_unit), kLights);
  scene.aim_camera(cloud.surfels.bounds().center(), Eigen::Vector3d(0, -1, 0.6),
                   Eigen::Vector3d(0, 0, 1), false);
  scene.pass->SetKernelStrategy(vtkSubsurfacePass::PAPER);
  scene.window->Render();
  const double plain = sss::cli::time_plain_points(scene, o.frames);
  std::fprintf(stderr, "  plain VTK points: %.4f s per frame\n", plain);
  for (const std::string& name : o.materials) {
    const sss::Material material = sss::Material::preset(name, 1.3, cloud.mm_per_unit);
    scene.set_material(material);
    sss::ReferenceSettings settings;
    settings.progress = print_progress;
    sss::ReferenceCacheStatus status;
    const sss::SurfelRadiance reference =
      sss::cached_reference(o.cache, cloud.surfels, material, kLights, settings, &status);
    std::fprintf(stderr, "  %s: reference %s (%s)\n", name.c_str(),
                 status.hit ? "from the cache" : "computed", status.file.string().c_str());
    if (!status.message.empty()) std::fprintf(stderr, "  %s\n", status.message.c_str());
    std::string over_budget;  // a strategy whose bake went over --max-bake-s
    std::vector<Setting> rows = sweep(o.quick);
    if (!o.settings.empty()) {
      rows.clear();
      for (const std::string& text : o.settings) rows.push_back(setting_of(text));
    }
    for (const Setting& s : rows) {
      Row row;
      row.cloud = cloud.name;
      row.points = cloud.surfels.size();
      row.material = name;
      row.plain_points_s = plain;
      if (s.strategy == over_budget) {
        std::fprintf(stderr, "  %-9s map %4d: skipped (a cheaper one took over %g s)\n",
                     s.strategy.c_str(), s.max_map, o.max_bake_s);
        continue;
      }
      measure(scene, s, o.frames, row);
      const sss::ErrorStats e = sss::compare_radiance(read_B(scene), reference.B);
      row.err_mean = e.mean, row.err_p99 = e.p99, row.err_max = e.max;
      row.err8_mean = e.srgb8_mean, row.err8_max = e.srgb8_max;
      print_row(row);
      write_row(csv, row);
      if (row.bake_s > o.max_bake_s) over_budget = s.strategy;
    }
  }
}

void run_scale(const Options& o, std::ostream& csv) {
  const bool procedural = o.scale_mesh.empty() && o.quick;
  const std::string mesh =
    o.scale_mesh.empty() ? sss::test::shared_data("dragon_vrip_res2.ply.gz") : o.scale_mesh;
  if (!procedural && mesh.empty()) {
    std::fprintf(stderr, "scale sweep skipped: dragon_vrip_res2.ply.gz is not in the shared data "
                         "folder (give --scale-mesh)\n");
    return;
  }
  const double mm_per_unit = procedural ? 1.0 : (o.scale_mesh.empty() ? 1000.0 : o.mm_per_unit);
  const sss::Material material = sss::Material::preset(o.materials[0], 1.3, mm_per_unit);
  std::vector<std::string> over_budget;
  for (std::size_t n : o.scale_points) {
    reset_peak_rss();
    sss::Stopwatch clock;
    Cloud cloud;
    if (procedural) {  // the torus's surface is 4 pi^2 R r = 8290 mm^2: spacing for n points
      cloud.surfels = sss::make_torus(30.0, 7.0, std::sqrt(8290.0 / static_cast<double>(n)));
      cloud.surfels.validate();
      cloud.name = "torus";
    } else {
      cloud.surfels = sss::cli::load_cloud(mesh, n).cloud;
      cloud.name = fs::path(mesh).filename().string();
    }
    std::fprintf(stderr, "scale: %zu surfels (%.1f s to make)\n", cloud.surfels.size(), clock.lap());
    auto window = sss::cli::make_render_window("egl", o.size, o.size);
    TranslucentScene scene(window, cloud.surfels, material, kLights);
    scene.aim_camera(cloud.surfels.bounds().center(), Eigen::Vector3d(0, -1, 0.6),
                     Eigen::Vector3d(0, 0, 1), false);
    scene.pass->SetKernelStrategy(vtkSubsurfacePass::PAPER);
    scene.window->Render();
    const double plain = sss::cli::time_plain_points(scene, o.frames);
    for (const std::string& strategy : o.scale_strategies) {
      if (std::find(over_budget.begin(), over_budget.end(), strategy) != over_budget.end()) {
        std::fprintf(stderr, "  %-9s skipped (a smaller cloud took over %g s)\n", strategy.c_str(),
                     o.max_bake_s);
        continue;
      }
      Row row;
      row.kind = "scale";
      row.cloud = cloud.name;
      row.points = cloud.surfels.size();
      row.material = material.name;
      row.plain_points_s = plain;
      const Setting s = setting_of(strategy);
      measure(scene, s, o.frames, row);
      row.peak_rss_mb = peak_rss_mb();
      print_row(row);
      write_row(csv, row);
      if (row.bake_s > o.max_bake_s) over_budget.push_back(strategy);
    }
  }
}

std::vector<Cloud> clouds_of(const Options& o) {
  std::vector<Cloud> clouds;
  if (o.quick) {
    Cloud torus{"torus", sss::make_torus(30.0, 7.0, kQuickSpacing), 1.0};
    torus.surfels.validate();
    clouds.push_back(std::move(torus));
    return clouds;
  }
  std::vector<std::pair<std::string, std::size_t>> files;
  double mm = o.mm_per_unit;
  if (o.clouds.empty()) {
    mm = 1000.0;
    for (const auto& [name, samples] : {std::pair<std::string, std::size_t>{"dragon_vrip_res2.ply.gz", 640826},
                                        {"stanford_bunny.ply", 0}}) {
      const std::string path = sss::test::shared_data(name);
      if (path.empty())
        std::fprintf(stderr, "%s is not in the shared data folder: left out\n", name.c_str());
      else
        files.emplace_back(path, samples);
    }
  } else {
    for (const std::string& path : o.clouds) files.emplace_back(path, o.samples);
  }
  for (const auto& [path, samples] : files) {
    std::fprintf(stderr, "reading %s%s\n", path.c_str(),
                 samples ? (" (" + std::to_string(samples) + " samples)").c_str() : "");
    sss::cli::LoadedCloud loaded = sss::cli::load_cloud(path, samples);
    loaded.cloud.radius *= 1.5;  // as sss_render's default --radius-scale
    std::string name = fs::path(path).filename().string();
    if (samples) name += " (" + std::to_string(loaded.cloud.size()) + " samples)";
    clouds.push_back({name, std::move(loaded.cloud), mm});
  }
  if (clouds.empty()) throw std::runtime_error("no cloud to measure (give a file)");
  return clouds;
}

int run(Options o) {
  if (o.quick) {
    o.materials = {"marble", "ketchup"};
    o.frames = std::min(o.frames, 3);
    o.scale_points = {2000, 4000, 8000};
    o.scale_strategies = {"paper", "near-far"};
    o.size = std::min(o.size, 256);
  }
  if (!o.settings.empty()) o.scale_points.clear();  // a custom sweep measures only itself
  fs::create_directories(o.out);
  const fs::path csv_path = o.out / "bench.csv";
  std::ofstream csv(csv_path);
  if (!csv) throw std::runtime_error("cannot write " + csv_path.string());
  csv << kColumns << '\n';
  sss::Stopwatch clock;
  for (const Cloud& cloud : clouds_of(o)) run_sweep(o, cloud, csv);
  run_scale(o, csv);
  csv.close();
  std::fprintf(stderr, "wrote %s (%.0f s)\n", csv_path.string().c_str(), clock.lap());
  const std::string report = std::string("/usr/bin/python3 '") + SSS_BENCH_REPORT + "' '" +
                             csv_path.string() + "' --out-dir '" + o.out.string() + "'";
  if (std::system(report.c_str()) != 0)
    throw std::runtime_error("bench_report.py failed (is python3-matplotlib installed?)");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(parse(argc, argv));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sss_bench: %s\n", e.what());
    return 1;
  }
}
