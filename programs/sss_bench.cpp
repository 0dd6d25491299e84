// sss_bench: speed against error. For each cloud and material it renders a sweep of settings
// (the default, cheaper and dearer near-far settings, the 2005 paper's as one row) and
// measures, in one run and one window: frame time with the light static and moving, the bake
// (the near-field table: a geometry or material change), the light's steps, the near-field
// table's memory, and the per-point error at 3000 points against the CPU reference (cached on
// disk); plain VTK points of the same cloud are the baseline. A scale sweep renders the mesh
// sampled to N points, and a synthetic room scanned from one station beside the same room
// sampled uniformly at the same counts. Writes CSV, then bench_report.py writes the Markdown
// table and the plots.
#include <vtkFloatArray.h>
#include <vtkRenderWindow.h>

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numeric>
#include <optional>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench_csv.h"
#include "cli_options.h"
#include "cloud_input.h"
#include "room_scan.h"
#include "error_metric.h"
#include "procedural_shapes.h"
#include "reference_cache.h"
#include "render_window.h"
#include "renderer_info.h"
#include "splat_coverage.h"
#include "stopwatch.h"
#include "translucent_scene.h"
#include "whole_file.h"

namespace {

// Path of a file in the shared data folder (../shared/data beside the checkout), or "" when it
// is absent.
std::string shared_data(const std::string& name) {
  const std::string path = std::string(SSS_DATA_DIR) + "/" + name;
  return std::ifstream(path).good() ? path : std::string();
}

namespace fs = std::filesystem;
using sss::cli::number;
using sss::cli::TranslucentScene;
using sss::bench::kColumns;
using sss::bench::Row;

const char* kUsage = R"(usage: sss_bench [CLOUD.pcd|.ply|.ply.gz|.obj|.xyz|.txt|.csv|.asc ...] [options]

Speed against error of the real-time path, in one run: a sweep of settings per cloud and
material, plain VTK points as the baseline, the CPU reference per point (cached), and a scale
sweep. Writes OUT/bench.csv, then OUT/bench.md, OUT/bench_tradeoff.png and OUT/bench_scale.png
(scripts/bench_report.py, Debian's python3-matplotlib).

Without CLOUD: the shared scans at their real scale (1000 mm per unit): the dragon
(dragon_vrip_res2.ply.gz) sampled to 640,826 points, the paper's dragon size; the Stanford
bunny's vertices; the Kinect scenes table_scene_mug_stereo_textured.pcd and
milk_cartoon_all_small_clorox.pcd; the LiDAR tile CSite1_red1-utm.pcd (in skin1). Each is lit
as the scan tests light it. Errors are at 3000 points drawn with a fixed seed.

options (default in brackets)
  --quick              a procedural torus of 8,300 points, marble and ketchup, three
                       settings, a scale sweep of 2,000-8,000 points: about a minute (the
                       test suite runs it to keep the benchmark working)
  --materials LIST     comma-separated presets [marble,skimmilk,ketchup; skin1 on the tile]
  --mm-per-unit F      for given clouds [1]
  --samples N          for given PLY meshes: N points sampled on the surface [0: vertices]
  --memory-cap MIB     largest memory a file or --samples may claim [half the physical memory]
  --sweep-mesh FILE    mesh the scale sweep samples [the shared dragon]
  --sweep-points LIST  point counts of the scale sweep, or none
                       [100000,300000,1000000,2000000,5000000]
  --sweep-strategies L settings the scale sweep times (as in --settings), or none; at each
                       point count it also times the view alone (blended splats and hard
                       discs, radiance given) [paper,near-far]
  --sweep-only         only the scale sweep (and the rooms)
  --rooms LIST         point counts of the room sweep, or none: a 10 x 6 x 3 m room open
                       to the sky, scanned from one station (density falling with range
                       and incidence, 3 mm range noise) and sampled uniformly, both read
                       as sss_render reads a PCD, timed like the scale sweep in its first
                       material [100000,1000000]
  --settings LIST      measure these settings instead of the sweep: comma-separated
                       quality presets (interactive, balanced, accurate) or
                       strategy[:map[:angle[:samples]]] (strategy near-far or paper; largest
                       map side; far-field opening angle; cell samples), e.g.
                       near-far:2048:0.6:16; unset fields keep the pass's defaults
  --frames N           frames per timing (a light-moving timing with bakes over 2 s uses 1)
                       [8]
  --size N             window N x N pixels [512]
  --max-bake-s S       once a setting's bake and light steps exceed S seconds, the scale
                       sweep skips that setting at larger point counts [300]
  --gpu N              draw on EGL device N [the first graphics card, else Mesa's software
                       device]; the renderer is printed and in every row of the CSV
  --out DIR            output folder [bench]
  --cache DIR          reference cache folder [$XDG_CACHE_HOME/sss, else ~/.cache/sss]
  --help               this text
)";

struct Options {
  std::vector<std::string> clouds;
  bool quick = false;
  bool scale_only = false;
  std::vector<std::string> materials{"marble", "skimmilk", "ketchup"};
  double mm_per_unit = 1.0;
  std::size_t samples = 0;
  std::size_t memory_cap = 0;  // 0: the loader's default
  std::string scale_mesh;
  std::vector<std::size_t> scale_points{100000, 300000, 1000000, 2000000, 5000000};
  std::vector<std::string> scale_strategies{"paper", "near-far"};
  std::vector<std::size_t> room_points{100000, 1000000};
  std::vector<std::string> settings;  // replaces the sweep when given
  int frames = 8;
  int size = 512;
  double max_bake_s = 300.0;
  int gpu = -1;  // EGL device; -1: the first hardware device, else the software one
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

// A flag's comma-separated point counts; "none": no count.
std::vector<std::size_t> point_counts(const std::string& flag, const std::string& list) {
  std::vector<std::size_t> counts;
  if (list != "none")
    for (const std::string& n : split(list)) counts.push_back(sss::cli::count(flag, n, 1e9));
  return counts;
}


// A setting of the pass; unset fields keep the pass's defaults.
struct Setting {
  std::string preset = "balanced";  // vtkSubsurfacePass's quality preset, then the fields below
  std::string strategy = "near-far";
  int max_map = 0, cell_samples = 0;  // 0: the preset's
  double opening_angle = 0;
  bool is_paper = false, is_default = false;
};

// Onto `pass`: the preset, then the fields given.
void apply(const Setting& s, vtkSubsurfacePass* pass) {
  pass->SetQualityPreset(s.preset);
  pass->SetKernelStrategyByName(s.strategy);
  if (s.max_map) pass->SetMaxMapSize(s.max_map);
  if (s.opening_angle) pass->SetOpeningAngle(s.opening_angle);
  if (s.cell_samples) pass->SetCellSamples(s.cell_samples);
}

// A quality preset's name ("interactive", "balanced", "accurate"), or
// "strategy[:map[:angle[:samples]]]" over the defaults, e.g. "near-far:1024:1:8"; "paper" is
// the paper's.
Setting setting_of(const std::string& text) {
  std::vector<std::string> f;
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, ':');) f.push_back(part);
  Setting s;
  vtkNew<vtkSubsurfacePass> pass;
  if (pass->SetQualityPreset(text)) {
    s.preset = text;
  } else {
    s.strategy = f.empty() ? text : f[0];
    if (!pass->SetKernelStrategyByName(s.strategy))
      throw std::invalid_argument("--settings: '" + text +
                                  "' is not a quality preset (interactive, balanced, accurate) "
                                  "nor starts with near-far or paper");
  }
  if (f.size() > 4) throw std::invalid_argument("--settings: '" + text + "' has more than 4 parts");
  if (f.size() > 1 && !f[1].empty()) {
    const int hi = pass->GetMaxMapSizeMaxValue();
    const double map = static_cast<double>(sss::cli::count("--settings map", f[1], hi));
    s.max_map = static_cast<int>(
        sss::cli::within("--settings map", map, pass->GetMaxMapSizeMinValue(), hi));
  }
  if (f.size() > 2 && !f[2].empty()) {
    s.opening_angle = sss::cli::within("--settings angle", number("--settings angle", f[2]),
                                       pass->GetOpeningAngleMinValue(),
                                       pass->GetOpeningAngleMaxValue());
  }
  if (f.size() > 3 && !f[3].empty()) {
    const int hi = pass->GetCellSamplesMaxValue();
    const double samples = static_cast<double>(sss::cli::count("--settings samples", f[3], hi));
    s.cell_samples = static_cast<int>(
        sss::cli::within("--settings samples", samples, pass->GetCellSamplesMinValue(), hi));
  }
  apply(s, pass);
  s.is_paper = s.strategy == "paper";
  s.is_default = !s.is_paper && pass->GetQualityPresetAsString() == "balanced";
  return s;
}

Options parse(int argc, char** argv) {
  Options o;
  for (sss::cli::Arguments args(argc, argv); args.next();) {
    const std::string& flag = args.flag();
    const auto value = [&args] { return args.value(); };
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
      o.samples = sss::cli::count(flag, value(), 1e9);
    } else if (flag == "--memory-cap") {
      o.memory_cap = sss::cli::memory_cap(flag, value());
    } else if (flag == "--sweep-mesh") {
      o.scale_mesh = value();
    } else if (flag == "--sweep-points") {
      o.scale_points = point_counts(flag, value());
    } else if (flag == "--sweep-strategies") {
      o.scale_strategies = split(value());
      if (o.scale_strategies == std::vector<std::string>{"none"}) o.scale_strategies.clear();
      for (const std::string& text : o.scale_strategies) setting_of(text);
    } else if (flag == "--rooms") {
      o.room_points = point_counts(flag, value());
    } else if (flag == "--sweep-only") {
      o.scale_only = true;
    } else if (flag == "--settings") {
      o.settings = split(value());
      for (const std::string& text : o.settings) setting_of(text);
    } else if (flag == "--frames") {
      o.frames = static_cast<int>(sss::cli::count(flag, value(), 100000));
    } else if (flag == "--size") {
      o.size = static_cast<int>(sss::cli::count(flag, value(), 16384));
    } else if (flag == "--max-bake-s") {
      o.max_bake_s = number(flag, value());
    } else if (flag == "--gpu") {
      o.gpu = static_cast<int>(sss::cli::count(flag, value(), 1023));
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

// The sweep: the paper's setting, the quality presets (balanced: the defaults), and a coarser
// far field alone.
std::vector<Setting> sweep(bool quick) {
  const Setting paper = setting_of("paper"), defaults = setting_of("balanced");
  if (quick) return {paper, defaults, setting_of("interactive")};
  return {paper, defaults, setting_of("interactive"), setting_of("near-far:4096:0.6"),
          setting_of("accurate")};
}

struct Cloud {
  std::string name;
  sss::SurfelCloud surfels;
  double mm_per_unit;
  Eigen::Vector3d light;           // towards the light
  Eigen::Vector3d view_dir, up;    // camera at the bounds centre + view_dir
  std::vector<std::string> materials;  // empty: --materials
};

// Lights and views as the scan tests use them (tests/test_gpu_scans.cpp): objects lit from
// the front, Kinect scenes from the sensor's side, the tile from above.
const Eigen::Vector3d kObjectLight(0.3, 0.4, -1.0), kSceneLight(0.3, -0.5, -1.0),
    kTileLight(0.2, 0.3, 1.0);
const Eigen::Vector3d kObjectView(0, -1, 0.6), kObjectUp(0, 0, 1);

// Peak resident memory since the last reset, MiB (Linux: /proc/self/status VmHWM).
double peak_rss_mb() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  return NAN;
}

void reset_peak_rss() { std::ofstream("/proc/self/clear_refs") << "5"; }

constexpr double kQuickSpacing = 1.0;  // mm: the quick mode's torus has about 8,300 points

// The points the error is measured at: 3000 of the cloud's, drawn with a fixed seed.
std::vector<std::size_t> error_points(std::size_t points) {
  std::vector<std::size_t> ids(points);
  std::iota(ids.begin(), ids.end(), std::size_t{0});
  std::mt19937 rng(1);
  std::shuffle(ids.begin(), ids.end(), rng);
  ids.resize(std::min<std::size_t>(3000, ids.size()));
  std::sort(ids.begin(), ids.end());
  return ids;
}

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
  apply(s, pass);
  scene.window->Render();
  row.strategy = s.strategy;
  row.is_paper = s.is_paper;
  row.is_default = s.is_default;
  row.map_size = s.is_paper ? 512 : pass->GetMaxMapSize();
  if (!s.is_paper) {
    row.opening_angle = pass->GetOpeningAngle();
    row.cell_samples = pass->GetCellSamples();
    row.near_field_mib = 16.0 * static_cast<double>(pass->GetLastNearFieldEntries()) / 1048576.0;
    row.lit_cells = static_cast<double>(pass->GetLastLitCells());
    row.map_s = pass->GetLastIlluminationSeconds();
    row.cells_s = pass->GetLastCellSeconds();
    row.pyramid_s = pass->GetLastPyramidSeconds();
    row.near_s = pass->GetLastNearFieldSeconds();
    row.far_s = pass->GetLastFarFieldSeconds();
    row.hand_over_s = pass->GetLastHandOverSeconds();
  } else {
    row.virtual_points = static_cast<double>(pass->GetLastVirtualPoints());
  }
  row.bake_s = pass->GetLastBakeSeconds();
  row.light_s = pass->GetLastIlluminationSeconds() + pass->GetLastSurfelSeconds();
  row.frame_static_s = sss::cli::time_light_static(scene, frames);
  row.frame_moving_s = sss::cli::time_light_moving(scene, row.light_s > 2.0 ? 1 : frames);
}

// "; light steps: map 0.1 s, ..." for a near-far row, "" for others.
std::string profile(const Row& r) {
  if (!std::isfinite(r.far_s)) return "";
  char text[200];
  std::snprintf(text, sizeof text,
                "; light steps: map %.3g s, cells %.3g s, pyramid %.3g s, near %.3g s, far "
                "%.3g s, hand-over %.3g s",
                r.map_s, r.cells_s, r.pyramid_s, r.near_s, r.far_s, r.hand_over_s);
  return text;
}

void print_row(const Row& r) {
  std::fprintf(stderr,
               "  %-8s map %4d angle %.2g samples %g: bake %.3f s, light steps %.3f s, static "
               "%.4f s (%.2fx), moving %.3f s (%.1fx), near field %.1f MiB, error mean %.3f %% "
               "p99 %.2f %% max %.1f %%%s\n",
               r.strategy.c_str(), r.map_size, r.opening_angle, r.cell_samples, r.bake_s,
               r.light_s, r.frame_static_s, r.frame_static_s / r.plain_points_s,
               r.frame_moving_s, r.frame_moving_s / r.plain_points_s, r.near_field_mib,
               100 * r.err_mean, 100 * r.err_p99, 100 * r.err_max, profile(r).c_str());
}

// An EGL window on the chosen device; the renderer that draws it is printed and goes into
// every row of the CSV.
std::string renderer_text;
vtkSmartPointer<vtkRenderWindow> make_window(const Options& o) {
  auto window = sss::cli::make_render_window("egl", o.size, o.size, o.gpu);
  const sss::cli::RendererInfo info = sss::cli::renderer_info(window);
  renderer_text = info.summary();
  std::fprintf(stderr, "drawn by %s\n", renderer_text.c_str());
  if (!info.warning().empty()) std::fprintf(stderr, "%s\n", info.warning().c_str());
  return window;
}

void emit(std::ostream& csv, Row& row) {
  row.renderer = renderer_text;
  write_row(csv, row);
}

void run_sweep(const Options& o, const Cloud& cloud, std::ostream& csv) {
  std::fprintf(stderr, "%s: %zu surfels\n", cloud.name.c_str(), cloud.surfels.size());
  const std::vector<std::string>& materials = cloud.materials.empty() ? o.materials : cloud.materials;
  const std::vector<sss::Light> lights{{cloud.light, 1.0}};
  auto window = make_window(o);
  TranslucentScene scene(window, cloud.surfels,
                         sss::Material::preset(materials[0], sss::kDefaultEta, cloud.mm_per_unit), lights);
  scene.aim_camera(cloud.surfels.positions, cloud.view_dir, cloud.up, false);
  scene.pass->SetKernelStrategy(vtkSubsurfacePass::PAPER);
  scene.window->Render();
  const double plain = sss::cli::time_plain_points(scene, o.frames);
  std::fprintf(stderr, "  plain VTK points: %.4f s per frame\n", plain);
  sss::ReferenceSettings settings;
  settings.progress = print_progress;
  settings.receivers = error_points(cloud.surfels.size());
  for (const std::string& name : materials) {
    const sss::Material material = sss::Material::preset(name, sss::kDefaultEta, cloud.mm_per_unit);
    scene.set_material(material);
    sss::ReferenceCacheStatus status;
    const sss::SurfelRadiance reference =
      sss::cached_reference(o.cache, cloud.surfels, material, lights, settings, &status);
    std::fprintf(stderr, "  %s: reference %s (%s)\n", name.c_str(),
                 status.hit ? "from the cache" : "computed", status.file.string().c_str());
    if (!status.message.empty()) std::fprintf(stderr, "  %s\n", status.message.c_str());
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
      measure(scene, s, o.frames, row);
      const std::vector<sss::Rgb> B = read_B(scene);
      std::vector<sss::Rgb> got, expected;
      for (std::size_t i : settings.receivers) {
        got.push_back(B[i]);
        expected.push_back(reference.B[i]);
      }
      const sss::ErrorStats e = sss::compare_radiance(got, expected);
      row.err_mean = e.mean, row.err_p99 = e.p99, row.err_max = e.max;
      row.err8_mean = e.srgb8_mean, row.err8_max = e.srgb8_max;
      print_row(row);
      emit(csv, row);
    }
  }
}

// The view alone, light static: the radiance given (steps 1-2 skipped), drawn as blended
// splats and as hard discs.
void run_view(const Options& o, TranslucentScene& scene, const Cloud& cloud, double plain,
              std::ostream& csv) {
  vtkNew<vtkFloatArray> given;
  given->SetNumberOfComponents(3);
  given->SetNumberOfTuples(static_cast<vtkIdType>(cloud.surfels.size()));
  given->Fill(0.5);
  scene.pass->SetPrecomputedRadiance(scene.actor, given);
  for (const bool blended : {true, false}) {
    if (blended) {
      scene.mapper->SetSplattingToBlended();
    } else {
      scene.mapper->SetSplattingToDiscs();
    }
    scene.window->Render();
    Row row;
    row.kind = "view";
    row.cloud = cloud.name;
    row.points = cloud.surfels.size();
    row.strategy = blended ? "blended" : "discs";
    row.plain_points_s = plain;
    row.frame_static_s = sss::cli::time_light_static(scene, o.frames);
    row.peak_rss_mb = peak_rss_mb();
    std::fprintf(stderr, "  view, %s: %.4f s per frame (%.2fx plain VTK points)\n",
                 row.strategy.c_str(), row.frame_static_s, row.frame_static_s / plain);
    emit(csv, row);
  }
  scene.mapper->SetSplattingToBlended();
  scene.pass->SetPrecomputedRadiance(scene.actor, nullptr);
}

// Times one cloud of a scale sweep in `material`: plain points, the view alone (with_view),
// then each of the sweep's settings that a smaller cloud did not put over the budget.
void time_at_scale(const Options& o, const Cloud& cloud, const sss::Material& material,
                   bool with_view, std::vector<std::string>& over_budget, std::ostream& csv) {
  auto window = make_window(o);
  TranslucentScene scene(window, cloud.surfels, material, {{cloud.light, 1.0}});
  scene.aim_camera(cloud.surfels.positions, cloud.view_dir, cloud.up, false);
  scene.pass->SetKernelStrategy(vtkSubsurfacePass::PAPER);
  scene.window->Render();
  const double plain = sss::cli::time_plain_points(scene, o.frames);
  if (with_view) run_view(o, scene, cloud, plain, csv);
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
    emit(csv, row);
    if (row.bake_s + row.light_s > o.max_bake_s) over_budget.push_back(strategy);
  }
}

void run_scale(const Options& o, std::ostream& csv) {
  const bool procedural = o.scale_mesh.empty() && o.quick;
  const std::string mesh =
    o.scale_mesh.empty() ? shared_data("dragon_vrip_res2.ply.gz") : o.scale_mesh;
  if (!procedural && mesh.empty()) {
    std::fprintf(stderr, "scale sweep skipped: dragon_vrip_res2.ply.gz is not in the shared data "
                         "folder (give --sweep-mesh)\n");
    return;
  }
  const double mm_per_unit = procedural ? 1.0 : (o.scale_mesh.empty() ? 1000.0 : o.mm_per_unit);
  const sss::Material material = sss::Material::preset(o.materials[0], sss::kDefaultEta, mm_per_unit);
  std::vector<std::string> over_budget;
  for (std::size_t n : o.scale_points) {
    reset_peak_rss();
    sss::Stopwatch clock;
    Cloud cloud{"", {}, mm_per_unit, kObjectLight, kObjectView, kObjectUp, {}};
    if (procedural) {  // the torus's surface is 4 pi^2 R r = 8290 mm^2: spacing for n points
      cloud.surfels = sss::make_torus(30.0, 7.0, std::sqrt(8290.0 / static_cast<double>(n)));
      cloud.surfels.validate();
      cloud.name = "torus";
    } else {
      cloud.surfels = sss::cli::load_cloud(mesh, n, o.memory_cap).cloud;
      cloud.name = fs::path(mesh).filename().string();
    }
    sss::assign_splat_radii(cloud.surfels);
    std::fprintf(stderr, "scale: %zu surfels (%.1f s to make)\n", cloud.surfels.size(), clock.lap());
    time_at_scale(o, cloud, material, true, over_budget, csv);
  }
}

// The rooms (room_scan.h) at each count, from one station and uniform, written as a PCD whose
// viewpoint is the station and read back as sss_render reads it (normals towards the station,
// isolated points left out, the measured surface, per-point radii where the spacing spreads).
// Lit from above through the open top and seen from above, at 1000 mm per unit.
void run_rooms(const Options& o, std::ostream& csv) {
  const sss::Material material = sss::Material::preset(o.materials[0], sss::kDefaultEta, 1000.0);
  constexpr double kRangeNoise = 0.003;  // m
  std::vector<std::string> over_budget[2];
  for (std::size_t n : o.room_points) {
    for (int uniform = 0; uniform < 2; ++uniform) {
      reset_peak_rss();
      sss::Stopwatch clock;
      const std::vector<Eigen::Vector3d> points = uniform
                                                    ? sss::uniform_open_room(n, kRangeNoise, 5)
                                                    : sss::open_room_scan(n, kRangeNoise, 5);
      const fs::path pcd = o.out / "room.pcd";
      sss::write_whole_file(pcd.string(), [&](std::ostream& out) {
        out << "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH "
            << points.size() << "\nHEIGHT 1\nVIEWPOINT " << sss::kRoomStation[0] << ' '
            << sss::kRoomStation[1] << ' ' << sss::kRoomStation[2] << " 1 0 0 0\nPOINTS "
            << points.size() << "\nDATA binary\n";
        for (const Eigen::Vector3d& p : points) {
          const float xyz[3] = {float(p.x()), float(p.y()), float(p.z())};
          out.write(reinterpret_cast<const char*>(xyz), sizeof xyz);
        }
      });
      Cloud cloud{uniform ? "room sampled uniformly" : "room from one station", {}, 1000.0,
                  Eigen::Vector3d(0.3, 0.2, 1.0), Eigen::Vector3d(0, -0.5, 1),
                  Eigen::Vector3d(0, 1, 0), {}};
      cloud.surfels = sss::cli::load_cloud(pcd.string(), 0, o.memory_cap).cloud;
      fs::remove(pcd);
      const sss::SplatRadii radii = sss::assign_splat_radii(cloud.surfels);
      std::fprintf(stderr, "%s: %zu surfels of %zu points, spacing spread %.1f (%.1f s to make)\n",
                   cloud.name.c_str(), cloud.surfels.size(), points.size(), radii.spacing_spread,
                   clock.lap());
      time_at_scale(o, cloud, material, false, over_budget[uniform], csv);
    }
  }
}

std::vector<Cloud> clouds_of(const Options& o) {
  std::vector<Cloud> clouds;
  if (o.quick) {
    Cloud torus{"torus", sss::make_torus(30.0, 7.0, kQuickSpacing), 1.0, kObjectLight,
                kObjectView, kObjectUp, {}};
    torus.surfels.validate();
    sss::assign_splat_radii(torus.surfels);
    clouds.push_back(std::move(torus));
    return clouds;
  }
  struct Scan {
    std::string file;
    std::size_t samples;
    Eigen::Vector3d light, view_dir, up;
    std::vector<std::string> materials;
  };
  std::vector<Scan> scans;
  double mm = o.mm_per_unit;
  if (o.clouds.empty()) {
    mm = 1000.0;
    const Eigen::Vector3d sensor_view(0, 0, -1), sensor_up(0, -1, 0);
    for (const Scan& scan : std::vector<Scan>{
             {"dragon_vrip_res2.ply.gz", 640826, kObjectLight, kObjectView, kObjectUp, {}},
             {"stanford_bunny.ply", 0, kObjectLight, kObjectView, kObjectUp, {}},
             {"table_scene_mug_stereo_textured.pcd", 0, kSceneLight, sensor_view, sensor_up, {}},
             {"milk_cartoon_all_small_clorox.pcd", 0, kSceneLight, sensor_view, sensor_up, {}},
             {"CSite1_red1-utm.pcd", 0, kTileLight, Eigen::Vector3d(0, -0.5, 1),
              Eigen::Vector3d(0, 1, 0), {"skin1"}}}) {
      Scan found = scan;
      found.file = shared_data(scan.file);
      if (found.file.empty())
        std::fprintf(stderr, "%s is not in the shared data folder: left out\n", scan.file.c_str());
      else
        scans.push_back(found);
    }
  } else {
    for (const std::string& path : o.clouds)
      scans.push_back({path, o.samples, kObjectLight, kObjectView, kObjectUp, {}});
  }
  for (const Scan& scan : scans) {
    std::fprintf(stderr, "reading %s%s\n", scan.file.c_str(),
                 scan.samples ? (" (" + std::to_string(scan.samples) + " samples)").c_str() : "");
    sss::cli::LoadedCloud loaded = sss::cli::load_cloud(scan.file, scan.samples, o.memory_cap);
    sss::assign_splat_radii(loaded.cloud);  // sss_render's default radii
    std::string name = fs::path(scan.file).filename().string();
    if (scan.samples) name += " (" + std::to_string(loaded.cloud.size()) + " samples)";
    clouds.push_back({name, std::move(loaded.cloud), mm, scan.light, scan.view_dir, scan.up,
                      scan.materials});
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
    o.room_points = {3000};
    o.size = std::min(o.size, 256);
  }
  if (!o.settings.empty()) {  // a custom sweep measures only itself
    o.scale_points.clear();
    o.room_points.clear();
  }
  fs::create_directories(o.out);
  const fs::path csv_path = o.out / "bench.csv";
  sss::Stopwatch clock;
  std::ostringstream csv;  // written whole once every row is measured
  csv << kColumns << '\n';
  if (!o.scale_only)
    for (const Cloud& cloud : clouds_of(o)) run_sweep(o, cloud, csv);
  run_scale(o, csv);
  run_rooms(o, csv);
  sss::write_whole_file(csv_path.string(), [&](std::ostream& out) { out << csv.str(); });
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
