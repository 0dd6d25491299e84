// sss_render: a translucent surfel cloud rendered on the CPU (reference or grid method).
#include <cstdio>
#include <fstream>
#include <iostream>
#include <stdexcept>

#include "camera_view.h"
#include "cli_options.h"
#include "grid_renderer.h"
#include "png_output.h"
#include "procedural_shapes.h"
#include "reference_renderer.h"
#include "stopwatch.h"

namespace {

using sss::cli::Options;

void print_progress(const char* what, std::size_t done, std::size_t total) {
  std::fprintf(stderr, "\r%s: %3.0f %% (%zu of %zu points)", what,
               total ? 100.0 * done / total : 100.0, done, total);
  if (done == total) std::fprintf(stderr, "\n");
}

std::string json_vector(const Eigen::Vector3d& v) {
  char text[128];
  std::snprintf(text, sizeof text, "[%.9g, %.9g, %.9g]", v.x(), v.y(), v.z());
  return text;
}

std::string json_rgb(const sss::Rgb& v) { return json_vector(Eigen::Vector3d(v[0], v[1], v[2])); }

void write_stats(const Options& o, const sss::Material& m, const sss::RadianceStats& s,
                 double seconds_image, const std::string& path) {
  const std::string partial = path + ".partial";
  {
    std::ofstream out(partial);
    out << "{\n  \"method\": \"" << o.method << "\",\n"
        << "  \"input\": \"" << (o.input.empty() ? "procedural torus" : o.input) << "\",\n"
        << "  \"material\": {\"name\": \"" << m.name << "\", \"sigma_a_per_mm\": "
        << json_rgb(m.sigma_a) << ", \"sigma_s_prime_per_mm\": " << json_rgb(m.sigma_s_prime)
        << ", \"eta\": " << json_rgb(m.eta) << ", \"mm_per_unit\": " << m.mm_per_unit << "},\n"
        << "  \"lights\": [";
    for (std::size_t i = 0; i < o.light_dirs.size(); ++i)
      out << (i ? ", " : "") << "{\"direction\": " << json_vector(o.light_dirs[i].normalized())
          << ", \"irradiance\": " << o.light_irradiance << "}";
    out << "],\n  \"camera\": {\"view_direction\": " << json_vector(o.view_dir.normalized())
        << ", \"up\": " << json_vector(o.up) << ", \"width\": " << o.width
        << ", \"height\": " << o.height << ", \"projection\": \"orthographic\"},\n"
        << "  \"counts\": {\"surfels\": " << s.surfels << ", \"lit_samples\": " << s.lit_samples
        << ", \"virtual_points\": " << s.virtual_points << "},\n"
        << "  \"illumination_map\": {\"texel_mm\": " << s.texel_mm << ", \"width\": "
        << s.map_width << ", \"height\": " << s.map_height
        << ", \"texel_per_z_r\": " << o.texel_per_z_r << "},\n"
        << "  \"grid\": {\"level\": " << s.grid_level << ", \"spacing_mm\": " << s.grid_spacing_mm
        << "},\n"
        << "  \"seconds\": {\"illumination\": " << s.seconds_illumination
        << ", \"source_tree\": " << s.seconds_tree
        << ", \"virtual_points\": " << s.seconds_virtual_points
        << ", \"surfels\": " << s.seconds_surfels << ", \"image\": " << seconds_image << "}\n}\n";
    if (!out.flush()) throw std::runtime_error("cannot write " + partial);
  }
  if (std::rename(partial.c_str(), path.c_str()) != 0) {
    std::remove(partial.c_str());
    throw std::runtime_error("cannot write " + path);
  }
}

int run(const Options& o) {
  const sss::Material material =
      o.custom_material ? sss::Material::custom(o.sigma_a, o.sigma_s, o.eta, o.scale)
                        : sss::Material::preset(o.material, o.eta, o.scale);
  std::vector<sss::DirectionalLight> lights;
  for (const auto& d : o.light_dirs) lights.push_back({d, o.light_irradiance});
  for (const auto& l : lights) l.validate();
  // The demo: a torus in mm whose 7 mm tube glows where the light comes from behind.
  const sss::SurfelCloud cloud = sss::make_torus(30.0, 7.0, 0.6);
  std::fprintf(stderr, "%zu surfels, %s, %s method\n", cloud.size(), material.name.c_str(),
               o.method.c_str());
  sss::SurfelRadiance radiance;
  if (o.method == "reference") {
    sss::ReferenceSettings settings;
    settings.illumination.texel_per_z_r = o.texel_per_z_r;
    settings.progress = [](std::size_t d, std::size_t t) { print_progress("reference", d, t); };
    radiance = sss::render_reference(cloud, material, lights, settings);
  } else {
    sss::GridSettings settings;
    settings.illumination.texel_per_z_r = o.texel_per_z_r;
    settings.progress = [](std::size_t d, std::size_t t) { print_progress("grid", d, t); };
    radiance = sss::render_grid(cloud, material, lights, settings);
  }
  sss::Stopwatch clock;
  sss::OrthoCamera camera;
  camera.view_direction = o.view_dir;
  camera.up = o.up;
  camera.width = o.width;
  camera.height = o.height;
  const sss::LinearImage image = sss::render_view(cloud, material, radiance.B, camera);
  const double seconds_image = clock.seconds();
  sss::cli::write_png(image, o.output_png);
  if (!o.linear_pfm.empty()) sss::write_pfm(image, o.linear_pfm);
  if (!o.stats_json.empty()) write_stats(o, material, radiance.stats, seconds_image, o.stats_json);
  std::fprintf(stderr, "wrote %s\n", o.output_png.c_str());
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
    return run(options);
  } catch (const std::exception& e) {
    std::cerr << "sss_render: " << e.what() << "\n";
    return 2;
  }
}
