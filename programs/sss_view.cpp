// sss_view: an interactive, Qt-free PCLVisualizer window showing a cloud translucent.
// Drag to orbit (PCL's usual mouse and keys); Ctrl+Shift and a drag turns the light, the keys
// below change the light, the material, the quality and the exposure; a line at the top shows
// the frame rate, the settings and whether a preview or the refined image is on screen.
#include <pcl/point_types.h>
#include <pcl/visualization/pcl_visualizer.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>
#include <vtkSubsurfacePass.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "cli_options.h"
#include "material.h"
#include "procedural_shapes.h"
#include "renderer_info.h"
#include "sssPclLightDrag.h"
#include "sssPclPendingEvents.h"
#include "sssPclTranslucentCloud.h"
#include "translucent_scene.h"

namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;
// With refinement, the input rests once no key or drag came for this long.
constexpr double kRestSeconds = 0.3;
constexpr double kStatusSeconds = 1.0;  // while refining, a frame this often shows the share done
constexpr double kNever = 3600.0;

std::string usage() {
  std::ostringstream text;
  text << R"(usage: sss_view [INPUT.pcd|.ply|.ply.gz|.obj|.xyz|.txt|.csv|.asc] [options]

Shows INPUT (default: a procedural torus, 30 mm across its tube ring) translucent in a
PCLVisualizer window. Needs an X display (or Xvfb).

options (default in brackets)
  --material NAME      measured preset [)" << sss::kDefaultPreset << R"(], one of)" << sss::cli::preset_list(23) << R"(
  --mm-per-unit F      millimetres per scene unit, e.g. 1000 for a scan in metres [1]
  --quality Q          interactive | balanced | accurate: how finely B is summed when the
                       light or material changes (balanced: the pass's defaults; interactive
                       coarser and faster, accurate finer and slower; costs and errors of
                       each in docs/benchmark/bench.md) [balanced]
  --samples N          sample N points on a PLY or OBJ mesh's surface instead of its vertices [0]
  --memory-cap MIB     largest memory the file or --samples may claim [half the physical memory]
  --isolated R|keep    leave out points whose mean distance to their 16 nearest exceeds R
                       times that of those neighbours (stray returns, flying pixels) [5]
  --denoise on|off     points onto the surface they measured, sized from the depth noise
                       measured around each, normals from it (sss_render --help) [on]
  --refine on|off      while the light or the material changes, frames show the 2005 paper's
                       method (a few plain frames per light move, tens of percent off: the
                       status line says how far at the last rest), and the quality's B
                       follows once the input rests for )" << kRestSeconds << R"( s [on]
  --fit surface|all    first frame holds 99 % of the points (surface) or all of them, as
                       PCL's reset (all; the r key resets so) [surface]
  --size WxH           window size in pixels [1024x768]
  --keys STRING        press these keys one per frame after the first (scripted demos)
  --frames N           quit after N frames (0: run until the window is closed) [0]
  --screenshot FILE    save a PNG of the window after the last scripted key (or the first frame)
  --screenshots PREFIX save a PNG of the first frame, of every frame that a key or a drag
                       changed and of every refined one: PREFIX-00.png, PREFIX-01.png, ...
  --help               this text

mouse (besides PCL's: drag to orbit, scroll to zoom)
  Ctrl+Shift+drag  turn the light ()" << sss::LightDrag::kDegreesPerPixel
       << R"( degrees a pixel; the camera stays)

keys (besides PCL's: r reset camera, j screenshot, q quit)
  k / K        rotate the light 15 degrees left / right around the view's up axis
  i / I        raise / lower the light 15 degrees
  m / M        next / previous material
  n            next quality (interactive, balanced, accurate)
  x / X        exposure up / down by 1.25x
  z            automatic exposure (the 99.5th percentile of the visible radiance is white)
  h            this list (and PCL's)
)";
  return text.str();
}

struct Options {
  std::string input;
  std::string material = sss::kDefaultPreset;
  double mm_per_unit = 1.0;
  sss::Quality quality = sss::Quality::Balanced;
  std::size_t samples = 0;
  std::size_t memory_cap = 0;  // 0: the loader's default
  double isolation_ratio = 5.0;  // 0: isolated points kept
  bool denoise = true;
  bool fit_all = false;
  int width = 1024, height = 768;
  std::string keys;
  int frames = 0;
  std::string screenshot;
  std::string screenshots;
  bool refine = true;
};

Options parse(int argc, char** argv) {
  Options o;
  for (sss::cli::Arguments args(argc, argv); args.next();) {
    const std::string& flag = args.flag();
    const auto value = [&args] { return args.value(); };
    if (flag == "--help" || flag == "-h") {
      std::fputs(usage().c_str(), stdout);
      std::exit(0);
    } else if (flag == "--material") {
      o.material = value();
    } else if (flag == "--mm-per-unit") {
      o.mm_per_unit = sss::cli::number(flag, value());
      if (!(o.mm_per_unit > 0)) throw std::invalid_argument("--mm-per-unit: needs a positive value");
    } else if (flag == "--quality") {
      if (!sss::qualityFromName(value(), o.quality))
        throw std::invalid_argument("--quality: use interactive, balanced or accurate");
    } else if (flag == "--samples") {
      o.samples = sss::cli::count(flag, value(), 1e9);
    } else if (flag == "--memory-cap") {
      o.memory_cap = sss::cli::memory_cap(flag, value());
    } else if (flag == "--isolated") {
      o.isolation_ratio = sss::cli::isolation_ratio(flag, value());
    } else if (flag == "--denoise") {
      o.denoise = sss::cli::on_off(flag, value());
    } else if (flag == "--fit") {
      o.fit_all = sss::cli::fit_all(flag, value());
    } else if (flag == "--size") {
      const std::string s = value();
      if (std::sscanf(s.c_str(), "%dx%d", &o.width, &o.height) != 2 || o.width < 16 ||
          o.height < 16 || o.width > 8192 || o.height > 8192)
        throw std::invalid_argument("--size: use WxH, 16 to 8192 pixels each");
    } else if (flag == "--keys") {
      o.keys = value();
    } else if (flag == "--frames") {
      o.frames = static_cast<int>(sss::cli::count(flag, value(), 1e6));
    } else if (flag == "--screenshot") {
      o.screenshot = value();
    } else if (flag == "--screenshots") {
      o.screenshots = value();
    } else if (flag == "--refine") {
      o.refine = sss::cli::on_off(flag, value());
    } else if (!flag.empty() && flag[0] == '-') {
      throw std::invalid_argument(flag + ": unknown option (see --help)");
    } else if (o.input.empty()) {
      o.input = flag;
    } else {
      throw std::invalid_argument("one input file only (got " + o.input + " and " + flag + ")");
    }
  }
  return o;
}

// The surfels' positions, for the camera's fit.
std::vector<Eigen::Vector3d> points_of(const sss::Surfels& surfels) {
  std::vector<Eigen::Vector3d> points(surfels.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    surfels.polydata->GetPoint(static_cast<vtkIdType>(i), points[i].data());
  return points;
}

// The procedural torus of the demo as a PCL cloud with normals.
pcl::PointCloud<pcl::PointNormal> torus() {
  const sss::SurfelCloud surfels = sss::make_torus(30.0, 7.0, 0.6);
  pcl::PointCloud<pcl::PointNormal> cloud;
  for (std::size_t i = 0; i < surfels.size(); ++i) {
    pcl::PointNormal p;
    p.getVector3fMap() = surfels.positions[i].cast<float>();
    p.getNormalVector3fMap() = surfels.normals[i].cast<float>();
    cloud.push_back(p);
  }
  return cloud;
}

// Light direction (towards the light) from azimuth and elevation around the first view.
struct LightRig {
  Eigen::Vector3d up, towards_camera, side;
  double azimuth = 150.0, elevation = 30.0;  // degrees; 180 is straight behind the object
  Eigen::Vector3d direction() const {
    const double a = azimuth * kDegree, e = elevation * kDegree;
    return std::cos(e) * (std::cos(a) * towards_camera + std::sin(a) * side) + std::sin(e) * up;
  }
};

struct FrameClock {
  std::chrono::steady_clock::time_point start, end;
  double last_seconds = 0.0;
  int frames = 0;
};

void on_render_start(vtkObject*, unsigned long, void* data, void*) {
  static_cast<FrameClock*>(data)->start = std::chrono::steady_clock::now();
}

void on_render_end(vtkObject*, unsigned long, void* data, void*) {
  auto* clock = static_cast<FrameClock*>(data);
  clock->end = std::chrono::steady_clock::now();
  clock->last_seconds = std::chrono::duration<double>(clock->end - clock->start).count();
  ++clock->frames;
}

struct Viewer {
  pcl::visualization::PCLVisualizer& pcl_viewer;
  sss::TranslucentCloud& cloud;
  LightRig rig;
  std::vector<std::string> materials = sss::Material::preset_names();
  std::size_t material_index = 0;
  bool changed = true;
  std::chrono::steady_clock::time_point last_input = std::chrono::steady_clock::now();

  void turn(double right_degrees, double up_degrees) {
    rig.azimuth += right_degrees;
    rig.elevation = std::clamp(rig.elevation + up_degrees, -90.0, 90.0);
    lights_changed();
  }

  void lights_changed() {
    cloud.setLights({rig.direction()});
    changed = true;
    last_input = std::chrono::steady_clock::now();
  }

  bool resting() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - last_input).count() >=
           kRestSeconds;
  }

  void press(const std::string& key) {
    if (key == "k" || key == "K") rig.azimuth += key == "k" ? 15.0 : -15.0;
    else if (key == "i" || key == "I")
      rig.elevation = std::clamp(rig.elevation + (key == "i" ? 15.0 : -15.0), -90.0, 90.0);
    else if (key == "m" || key == "M") {
      const std::size_t n = materials.size();
      material_index = (material_index + (key == "m" ? 1 : n - 1)) % n;
      cloud.setMaterial(materials[material_index]);
    } else if (key == "n") {
      cloud.setQuality(static_cast<sss::Quality>((static_cast<int>(cloud.quality()) + 1) % 3));
    } else if (key == "x" || key == "X") {
      cloud.setExposure(cloud.exposure() * (key == "x" ? 1.25 : 0.8));
    } else if (key == "z") {
      cloud.autoExpose();
    } else if (key == "h") {
      std::fputs(usage().c_str(), stdout);
      std::printf("drawn by %s\n",
                  sss::cli::renderer_info(pcl_viewer.getRenderWindow()).summary().c_str());
      std::printf("last light move: %s\n", cloud.pass()->GetLastLightMoveProfile().c_str());
      return;
    } else {
      return;
    }
    lights_changed();
  }
};

void on_key(const pcl::visualization::KeyboardEvent& event, void* data) {
  if (event.keyDown()) static_cast<Viewer*>(data)->press(event.getKeySym());
}

int run(const Options& o) {
  pcl::visualization::PCLVisualizer pcl_viewer("sss_view");
  pcl_viewer.setSize(o.width, o.height);
  pcl_viewer.setBackgroundColor(0.0, 0.0, 0.0);

  sss::TranslucentCloudOptions settings;
  settings.material = o.material;
  settings.millimetres_per_unit = o.mm_per_unit;
  settings.quality = o.quality;
  settings.surfels.drop_isolated = o.isolation_ratio > 0.0;
  if (settings.surfels.drop_isolated) settings.surfels.isolation_ratio = o.isolation_ratio;
  settings.surfels.denoise = o.denoise;
  sss::TranslucentCloud::Ptr cloud;
  if (o.input.empty()) {
    cloud = sss::addTranslucentCloud(pcl_viewer, torus(), "cloud", settings);
  } else {
    std::fprintf(stderr, "reading %s\n", o.input.c_str());
    sss::LoadOptions load;
    load.mesh_samples = o.samples;
    load.memory_cap = o.memory_cap;
    const auto loaded = sss::loadPointCloud<pcl::PointXYZRGBNormal>(o.input, load);
    std::fprintf(stderr, "%s\n", loaded.description.c_str());
    cloud = sss::addTranslucentSurfels(pcl_viewer, sss::makeSurfels(loaded, settings.surfels),
                                       "cloud", settings);
  }
  std::fprintf(stderr, "%s\n", cloud->surfels().summary().c_str());

  pcl_viewer.resetCamera();
  vtkRenderer* renderer = pcl_viewer.getRendererCollection()->GetFirstRenderer();
  if (!o.fit_all) sss::cli::frame_points(renderer, points_of(cloud->surfels()));
  vtkCamera& camera = *renderer->GetActiveCamera();
  Viewer viewer{pcl_viewer, *cloud, {}};
  double up[3], forward[3];
  camera.GetViewUp(up);
  camera.GetDirectionOfProjection(forward);
  viewer.rig.up = Eigen::Vector3d(up[0], up[1], up[2]).normalized();
  viewer.rig.towards_camera = -Eigen::Vector3d(forward[0], forward[1], forward[2]).normalized();
  viewer.rig.side = viewer.rig.up.cross(viewer.rig.towards_camera);
  for (std::size_t i = 0; i < viewer.materials.size(); ++i)
    if (viewer.materials[i] == o.material) viewer.material_index = i;
  cloud->setLights({viewer.rig.direction()});
  cloud->setRefinement(o.refine);
  cloud->setRefinementRest(kNever);  // the loop below says when the input rests
  pcl_viewer.registerKeyboardCallback(on_key, &viewer);
  sss::LightDrag drag(pcl_viewer, [&viewer](double right, double up) { viewer.turn(right, up); });

  FrameClock clock;
  vtkNew<vtkCallbackCommand> start, end;
  start->SetCallback(on_render_start);
  start->SetClientData(&clock);
  end->SetCallback(on_render_end);
  end->SetClientData(&clock);
  pcl_viewer.getRenderWindow()->AddObserver(vtkCommand::StartEvent, start);
  pcl_viewer.getRenderWindow()->AddObserver(vtkCommand::EndEvent, end);

  const auto status = [&] {
    char fps[64];
    std::snprintf(fps, sizeof fps, "%.1f fps (%.0f ms) | ", 1.0 / std::max(clock.last_seconds, 1e-6),
                  1000.0 * clock.last_seconds);
    return fps + cloud->settingsLine() + " | h: keys";
  };
  int shots = 0;
  int shown_frame = -1;
  int noted_frame = -1;  // the frame whose state the status line holds; no frame drew it yet
                         // while clock.frames is still that frame
  // Puts the state of the frame just drawn in the status line without drawing again: the next
  // frame shows it (a drag's, a refinement's next part), or draw_status once the input rests.
  bool noted_preparing = false;  // the status line says the bake's thread runs
  const auto note = [&] {
    noted_preparing = cloud->refinementPreparing();
    const std::string line = status();  // the time of the frame that ran the steps
    pcl_viewer.updateText(line, 10, o.height - 30, 16, 1.0, 1.0, 1.0, "sss_status");
    shown_frame = noted_frame = clock.frames;
    std::fprintf(stderr, "%s\n", line.c_str());
  };
  // Draws the status line (a frame with unchanged inputs runs no step) and writes the window
  // with --screenshots when asked.
  const auto draw_status = [&](bool shot) {
    pcl_viewer.getRenderWindow()->Render();
    shown_frame = clock.frames;
    if (shot && !o.screenshots.empty()) {
      char name[32];
      std::snprintf(name, sizeof name, "-%02d.png", shots++);
      pcl_viewer.saveScreenshot(o.screenshots + name);
    }
  };
  const auto show = [&](bool shot) {
    note();
    draw_status(shot);
  };

  std::fprintf(stderr, "first frame (steps 1-2 run now)...\n");
  pcl_viewer.addText("", 10, o.height - 30, 16, 1.0, 1.0, 1.0, "sss_status");
  pcl_viewer.getRenderWindow()->Render();
  std::fprintf(stderr, "drawn by %s\n",
               sss::cli::renderer_info(pcl_viewer.getRenderWindow()).summary().c_str());
  cloud->autoExpose();
  show(true);
  viewer.changed = false;
  bool exposed_refined = !cloud->refinementPending();  // else again once refined
  std::size_t next_key = 0;
  while (!pcl_viewer.wasStopped()) {
    if (next_key < o.keys.size() && !drag.dragging())
      viewer.press(std::string(1, o.keys[next_key++]));
    if (viewer.changed) {
      viewer.changed = false;
      pcl_viewer.getRenderWindow()->Render();
      viewer.last_input = std::chrono::steady_clock::now();  // the rest counts from the preview
      if (o.screenshots.empty())
        note();  // a drag's next frame, or the rest, draws it
      else
        show(true);
    } else if (clock.frames != shown_frame) {  // a camera move: its frame rate
      pcl_viewer.updateText(status(), 10, o.height - 30, 16, 1.0, 1.0, 1.0, "sss_status");
      shown_frame = clock.frames;
      viewer.last_input = std::chrono::steady_clock::now();  // an orbit is input too
    } else if (cloud->refinementPending() && viewer.resting() && !drag.dragging() &&
               next_key >= o.keys.size()) {
      cloud->setRefinementRest(0.0);  // the next part of the refinement is due now
      const bool due = cloud->refinementPartDue();
      if (due) cloud->refinePart();  // between frames: the parts draw no view
      cloud->setRefinementRest(kNever);
      if (!due) {
        // The bake's thread is at work: the input only, no frame that would redraw the preview
        // and take the processors from it (but the one that says so).
        if (noted_frame == clock.frames) draw_status(false);
        sss::processPendingEvents(pcl_viewer.getRenderWindow()->GetInteractor());
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        continue;
      }
      const bool refined = !cloud->refinementPending();
      if (refined && !exposed_refined) {
        cloud->autoExpose();
        exposed_refined = true;
      }
      if (refined)
        show(true);
      else if (cloud->refinementPreparing() != noted_preparing ||
               std::chrono::duration<double>(std::chrono::steady_clock::now() - clock.end)
                 .count() >= kStatusSeconds)
        show(false);  // the bake's thread started or ended, or how far it has come
      // The next part follows at once: the input queued meanwhile, without waiting for more.
      sss::processPendingEvents(pcl_viewer.getRenderWindow()->GetInteractor());
      continue;
    } else if (noted_frame == clock.frames && viewer.resting() && !drag.dragging()) {
      draw_status(false);  // no frame followed the last change's
    }
    pcl_viewer.spinOnce(20);
    if (!o.screenshot.empty() && next_key == o.keys.size() && !cloud->refinementPending()) {
      pcl_viewer.getRenderWindow()->Render();
      pcl_viewer.saveScreenshot(o.screenshot);
      std::fprintf(stderr, "wrote %s\n", o.screenshot.c_str());
      next_key = o.keys.size() + 1;  // once
    }
    if (o.frames > 0 && clock.frames >= o.frames && !cloud->refinementPending()) break;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Options options = parse(argc, argv);
    if (!std::getenv("DISPLAY") || !*std::getenv("DISPLAY")) {
      std::fprintf(stderr, "sss_view: DISPLAY is not set; it needs an X display (or run it under "
                           "xvfb-run; for images without a display use sss_render)\n");
      return 2;
    }
    return run(options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sss_view: %s\n", e.what());
    return 1;
  }
}
