// sss_render: a point cloud rendered offscreen as a translucent material, by the real-time GPU
// method (vtkSubsurfacePass) or by the CPU reference, through the same VTK view.
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkUnsignedCharArray.h>
#include <vtkProperty.h>
#include <vtkVertexGlyphFilter.h>
#include <vtkLightCollection.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSubsurfacePass.h>
#include <vtkSurfelMapper.h>
#include <vtkTranslucentMaterial.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <stdexcept>

#include "baked_ply.h"
#include "cli_options.h"
#include "camera_view.h"
#include "cloud_input.h"
#include "isolated_points.h"
#include "linear_image.h"
#include "png_output.h"
#include "procedural_shapes.h"
#include "reference_renderer.h"
#include "render_window.h"
#include "renderer_info.h"
#include "translucent_scene.h"
#include "stopwatch.h"
#include "whole_file.h"

namespace {

using sss::cli::Options;

void print_progress(std::size_t done, std::size_t total) {
  std::fprintf(stderr, "\rreference: %3.0f %% (%zu of %zu points)",
               total ? 100.0 * done / total : 100.0, done, total);
  if (done == total) std::fprintf(stderr, "\n");
}

std::string json_vector(const Eigen::Vector3d& v) {
  char text[128];
  std::snprintf(text, sizeof text, "[%.9g, %.9g, %.9g]", v.x(), v.y(), v.z());
  return text;
}

// A JSON string literal: quotes, backslashes and control characters escaped.
std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
      out += escaped;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string json_rgb(const sss::Rgb& v) { return json_vector(Eigen::Vector3d(v[0], v[1], v[2])); }

struct Timings {
  double load = 0, reference = 0, first_frame = 0, camera_frame = 0;
  double light_static = 0, light_moving = 0, plain_points = 0;  // mean seconds per frame
};

// What the load left out as isolated and the noise it measured (cloud_input.h).
struct LoadFindings {
  std::size_t left_out = 0;
  double largest_ratio = 0.0;
  bool denoised = false;
  double noise_median = 0.0, noise_p90 = 0.0;
};

void write_stats(const Options& o, const sss::Material& m, const sss::SurfelCloud& cloud,
                 const LoadFindings& found, const std::vector<sss::Light>& lights,
                 vtkSubsurfacePass* pass,
                 const sss::cli::RendererInfo& renderer, const Timings& t,
                 const std::string& path) {
  sss::write_whole_file(path, [&](std::ostream& out) {
    out << "{\n  \"method\": \"" << o.method << "\",\n  \"backend\": \"" << o.backend
        << "\",\n  \"renderer\": {\"gl_vendor\": " << json_string(renderer.gl_vendor)
        << ", \"gl_renderer\": " << json_string(renderer.gl_renderer)
        << ", \"gl_version\": " << json_string(renderer.gl_version)
        << ", \"context\": " << json_string(renderer.context)
        << ", \"software\": " << (renderer.software ? "true" : "false") << "},\n"
        << "  \"strategy\": \"" << pass->GetKernelStrategyAsString() << "\",\n"
        << "  \"input\": " << json_string(o.input.empty() ? "procedural torus" : o.input) << ",\n"
        << "  \"material\": {\"name\": \"" << m.name << "\", \"sigma_a_per_mm\": "
        << json_rgb(m.sigma_a) << ", \"sigma_s_prime_per_mm\": " << json_rgb(m.sigma_s_prime)
        << ", \"eta\": " << json_rgb(m.eta) << ", \"mm_per_unit\": " << m.mm_per_unit << "},\n"
        << "  \"lights\": [";
    for (std::size_t i = 0; i < lights.size(); ++i) {
      out << (i ? ", " : "") << "{\"direction\": " << json_vector(lights[i].direction.normalized());
      if (lights[i].positional)
        out << ", \"position\": " << json_vector(lights[i].position)
            << ", \"attenuation\": " << json_vector(lights[i].attenuation);
      out << ", \"irradiance\": " << lights[i].irradiance << "}";
    }
    out << "],\n  \"camera\": {\"view_direction\": " << json_vector(o.view_dir.normalized())
        << ", \"up\": " << json_vector(o.up) << ", \"width\": " << o.width
        << ", \"height\": " << o.height << ", \"projection\": \""
        << (o.ortho ? "orthographic" : "perspective") << "\", \"fit\": \""
        << (o.fit_all ? "all" : "surface") << "\"},\n"
        << "  \"isolated_points\": {\"ratio\": " << o.isolation_ratio
        << ", \"neighbours\": " << sss::IsolationSettings{}.neighbours
        << ", \"left_out\": " << found.left_out
        << ", \"largest_ratio\": " << found.largest_ratio << "},\n"
        << "  \"measured_surface\": {\"denoised\": " << (found.denoised ? "true" : "false")
        << ", \"noise_median\": " << found.noise_median
        << ", \"noise_p90\": " << found.noise_p90 << "},\n"
        << "  \"counts\": {\"surfels\": " << cloud.size()
        << ", \"lit_cells\": " << pass->GetLastLitCells()
        << ", \"refined_cells\": " << pass->GetLastRefinedCells()
        << ", \"near_field_entries\": " << pass->GetLastNearFieldEntries()
        << ", \"virtual_points\": " << pass->GetLastVirtualPoints() << "},\n"
        << "  \"settings\": {\"surfel_radius\": " << cloud.radius
        << ", \"texel_per_radius\": " << pass->GetTexelPerRadius()
        << ", \"max_map_size\": " << pass->GetMaxMapSize()
        << ", \"map_width\": " << pass->GetLastMapWidth()
        << ", \"map_height\": " << pass->GetLastMapHeight()
        << ", \"texel_mm\": " << pass->GetLastTexelMillimetres()
        << ", \"cell_samples\": " << pass->GetCellSamples()
        << ", \"near_reach_mm\": " << pass->GetLastNearReachMillimetres()
        << ", \"far_from_mm\": " << pass->GetLastFarFromMillimetres()
        << ", \"opening_angle\": " << pass->GetOpeningAngle()
        << ", \"group_diffusion_lengths\": " << pass->GetMaxGroupDiffusionLengths()
        << ", \"grid_level\": " << pass->GetLastGridLevel()
        << ", \"grid_spacing_mm\": " << pass->GetLastGridSpacingMillimetres()
        << ", \"exposure\": " << pass->GetExposure() << "},\n"
        << "  \"steps_run\": {\"bake\": " << pass->GetBakeRuns()
        << ", \"illumination\": " << pass->GetIlluminationRuns()
        << ", \"surfels\": " << pass->GetSurfelRuns() << ", \"view\": " << pass->GetViewRuns()
        << "},\n"
        << "  \"seconds\": {\"load\": " << t.load << ", \"reference\": " << t.reference
        << ", \"bake\": " << pass->GetLastBakeSeconds()
        << ", \"illumination\": " << pass->GetLastIlluminationSeconds()
        << ", \"surfels\": " << pass->GetLastSurfelSeconds()
        << ", \"first_frame\": " << t.first_frame
        << ", \"camera_only_frame\": " << t.camera_frame << "},\n"
        << "  \"light_move_seconds\": {\"light_map\": " << pass->GetLastIlluminationSeconds()
        << ", \"cells\": " << pass->GetLastCellSeconds()
        << ", \"pyramid\": " << pass->GetLastPyramidSeconds()
        << ", \"near_field\": " << pass->GetLastNearFieldSeconds()
        << ", \"far_field\": " << pass->GetLastFarFieldSeconds()
        << ", \"hand_over\": " << pass->GetLastHandOverSeconds() << "},\n"
        << "  \"frames\": {\"count\": " << o.frames
        << ", \"light_static_seconds\": " << t.light_static
        << ", \"light_moving_seconds\": " << t.light_moving
        << ", \"plain_vtk_points_seconds\": " << t.plain_points << "}\n}\n";
  });
}

int run(const Options& o) {
  sss::Stopwatch clock;
  Timings timings;
  const sss::Material material =
      o.custom_material ? sss::Material::custom(o.sigma_a, o.sigma_s, o.eta, o.mm_per_unit)
                        : sss::Material::preset(o.material, o.eta, o.mm_per_unit);
  sss::SurfelCloud cloud;
  LoadFindings found;
  if (o.input.empty()) {
    cloud = sss::make_torus(30.0, 7.0, 0.6);  // mm; its 7 mm tube glows when lit from behind
    cloud.validate();
  } else {
    sss::cli::LoadedCloud loaded =
      sss::cli::load_cloud(o.input, o.mesh_samples, o.memory_cap, o.isolation_ratio, o.denoise);
    found = {loaded.isolated, loaded.largest_isolation, loaded.denoised, loaded.noise_median,
                 loaded.noise_p90};
    std::fprintf(stderr, "%s\n", loaded.description.c_str());
    cloud = std::move(loaded.cloud);
  }
  std::fprintf(stderr, "%s\n", sss::cli::apply_splat_radii(o, cloud).c_str());
  timings.load = clock.lap();
  std::fprintf(stderr, "%zu surfels (radius %g), %s, %s method on %s\n", cloud.size(),
               cloud.radius, material.name.c_str(), o.method.c_str(), o.backend.c_str());

  vtkSmartPointer<vtkRenderWindow> window =
      sss::cli::make_render_window(o.backend, o.width, o.height, o.gpu);
  const sss::cli::RendererInfo renderer = sss::cli::renderer_info(window);
  std::fprintf(stderr, "drawn by %s\n", renderer.summary().c_str());
  if (!renderer.warning().empty()) std::fprintf(stderr, "%s\n", renderer.warning().c_str());
  const std::vector<sss::Light> lights = sss::cli::lights_of(o, cloud.bounds().center());
  sss::cli::TranslucentScene scene(window, cloud, material, lights);
  vtkSubsurfacePass* pass = scene.pass;
  vtkActor* actor = scene.actor;
  sss::cli::apply_pass_settings(o, pass);
  if (o.splatting == "discs") scene.mapper->SetSplattingToDiscs();
  pass->SetExposure(o.exposure);
  pass->SetCaptureLinearImage(!o.linear_pfm.empty() || o.exposure == 0.0);
  scene.aim_camera(cloud.positions, o.view_dir, o.up, o.ortho, o.fit_all);
  vtkCamera* camera = scene.renderer->GetActiveCamera();

  if (o.method == "reference") {
    sss::ReferenceSettings settings;
    settings.progress = print_progress;
    const sss::SurfelRadiance reference = sss::render_reference(cloud, material, lights, settings);
    vtkNew<vtkFloatArray> B;
    B->SetNumberOfComponents(3);
    B->SetNumberOfTuples(static_cast<vtkIdType>(cloud.size()));
    for (std::size_t i = 0; i < cloud.size(); ++i)
      B->SetTuple3(static_cast<vtkIdType>(i), reference.B[i][0], reference.B[i][1],
                   reference.B[i][2]);
    pass->SetPrecomputedRadiance(actor, B);
    timings.reference = clock.lap();
  }
  clock.lap();
  window->Render();
  timings.first_frame = clock.lap();
  if (pass->GetLastTranslucentActors() != 1)
    throw std::runtime_error("the cloud could not be rendered translucent (see the errors above)");
  vtkNew<vtkFloatArray> B;
  if (!pass->GetSurfelRadiance(actor, B)) throw std::runtime_error("no radiance was computed");
  if (o.exposure == 0.0) {  // automatic: the 99.5th percentile of the visible Lo maps to white
    const double white = pass->GetLinearImageQuantile(0.995);
    pass->SetExposure(white > 0.0 ? 1.0 / white : 1.0);
  }
  camera->Modified();  // a camera-only change: step 3 alone
  window->Render();
  timings.camera_frame = clock.lap();

  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  sss::cli::write_png(grab->GetOutput(), o.output_png);
  if (!o.linear_pfm.empty()) {
    vtkFloatArray* linear = pass->GetLinearImage();
    sss::LinearImage image(pass->GetLinearImageWidth(), pass->GetLinearImageHeight());
    for (vtkIdType p = 0; p < linear->GetNumberOfTuples(); ++p) {
      image.radiance[p] = {linear->GetValue(3 * p), linear->GetValue(3 * p + 1),
                           linear->GetValue(3 * p + 2)};
      image.covered[p] = linear->GetValue(3 * p) > 0 || linear->GetValue(3 * p + 1) > 0 ||
                         linear->GetValue(3 * p + 2) > 0;
    }
    sss::write_pfm(image, o.linear_pfm);
  }
  if (!o.bake_ply.empty()) {
    double eye[3];
    camera->GetPosition(eye);
    std::vector<sss::Rgb> radiance(cloud.size());
    for (std::size_t i = 0; i < cloud.size(); ++i)
      for (int ch = 0; ch < 3; ++ch) radiance[i][ch] = B->GetValue(static_cast<vtkIdType>(3 * i + ch));
    const std::vector<sss::Rgb> Lo =
      o.ortho ? sss::outgoing_radiance(cloud, material, radiance, o.view_dir)
              : sss::outgoing_radiance_to_eye(cloud, material, radiance,
                                              Eigen::Vector3d(eye[0], eye[1], eye[2]));
    sss::cli::write_baked_ply(cloud.positions, cloud.normals, Lo, o.bake_ply);
  }
  if (o.frames > 0) {
    timings.light_static = sss::cli::time_light_static(scene, o.frames);
    timings.light_moving = sss::cli::time_light_moving(scene, o.frames);
    timings.plain_points = sss::cli::time_plain_points(scene, o.frames);
    std::fprintf(stderr,
                 "frames: light static %.4f s, light moving %.4f s, plain VTK points %.4f s "
                 "(ratios %.2f and %.2f)\n",
                 timings.light_static, timings.light_moving, timings.plain_points,
                 timings.light_static / timings.plain_points,
                 timings.light_moving / timings.plain_points);
  }
  if (o.method == "gpu" && scene.pass->GetSurfelRuns() > 0)
    std::fprintf(stderr, "last light move: %s\n", scene.pass->GetLastLightMoveProfile().c_str());
  if (!o.stats_json.empty())
    write_stats(o, material, cloud, found, lights, pass, renderer, timings, o.stats_json);
  std::fprintf(stderr, "wrote %s (first frame %.3f s, camera-only frame %.3f s)\n",
               o.output_png.c_str(), timings.first_frame, timings.camera_frame);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Options options = sss::cli::parse(argc, argv);
    if (options.help) {
      std::cout << sss::cli::usage();
      return 0;
    }
    sss::cli::prepare_backend(options.backend, argc, argv);
    return run(options);
  } catch (const std::exception& e) {
    std::cerr << "sss_render: " << e.what() << "\n";
    return 2;
  }
}
