#include "cli_options.h"

#include <vtkNew.h>
#include <vtkSubsurfacePass.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "quality_settings.h"
#include "splat_coverage.h"

namespace sss::cli {
double number(const std::string& flag, const std::string& text) {
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !std::isfinite(v))
    throw std::invalid_argument(flag + ": '" + text + "' is not a finite number");
  return v;
}

std::size_t count(const std::string& flag, const std::string& text, double hi) {
  const double v = number(flag, text);
  if (v < 0 || v > hi || v != std::floor(v)) {
    std::ostringstream msg;
    msg << flag << ": needs a whole number from 0 to " << hi;
    throw std::invalid_argument(msg.str());
  }
  return static_cast<std::size_t>(v);
}

double within(const std::string& flag, double value, double lo, double hi) {
  if (value < lo || value > hi) {
    std::ostringstream msg;
    msg << flag << ": needs a value from " << lo << " to " << hi;
    throw std::invalid_argument(msg.str());
  }
  return value;
}

std::size_t memory_cap(const std::string& flag, const std::string& text) {
  const std::size_t mib = count(flag, text, 1e9);
  if (mib == 0) throw std::invalid_argument(flag + ": needs at least 1 MiB");
  return mib << 20;
}

namespace {

std::vector<double> numbers(const std::string& flag, const std::string& text, std::size_t count) {
  std::vector<double> values;
  std::stringstream parts(text);
  std::string part;
  while (std::getline(parts, part, ',')) values.push_back(number(flag, part));
  if (values.size() != count) {
    std::ostringstream msg;
    msg << flag << ": '" << text << "' needs " << count << " comma-separated numbers";
    throw std::invalid_argument(msg.str());
  }
  return values;
}

int whole(const std::string& flag, const std::string& text, int lo, int hi) {
  const double v = number(flag, text);
  if (v < lo || v > hi || v != std::floor(v)) {
    std::ostringstream msg;
    msg << flag << ": needs a whole number from " << lo << " to " << hi;
    throw std::invalid_argument(msg.str());
  }
  return static_cast<int>(v);
}

Eigen::Vector3d direction(const std::string& flag, const std::string& text) {
  const auto v = numbers(flag, text, 3);
  const Eigen::Vector3d d(v[0], v[1], v[2]);
  if (d.norm() == 0.0) throw std::invalid_argument(flag + ": the direction must not be zero");
  return d;
}

}  // namespace

std::string preset_list(std::size_t indent) {
  std::string text, line;
  for (const std::string& name : Material::preset_names()) {
    if (!line.empty() && indent + line.size() + 1 + name.size() > 92) {
      text += "\n" + std::string(indent, ' ') + line;
      line.clear();
    }
    line += (line.empty() ? "" : " ") + name;
  }
  return text + "\n" + std::string(indent, ' ') + line;
}

std::string usage() {
  vtkNew<vtkSubsurfacePass> pass;  // its defaults are the defaults below
  std::ostringstream text;
  text << R"(sss_render: renders a point cloud as a translucent material (dipole diffusion, Jensen 2001;
real-time method after Oda et al. 2005) offscreen, to PNG (tone-mapped sRGB) and optionally
linear radiance (PFM), per-point radiance (PLY) and JSON stats.

usage: sss_render [INPUT.pcd|.ply|.ply.gz|.obj|.xyz|.txt|.csv|.asc] [options]
       (no input: a procedural marble torus the project generates, in mm)

  --output F.png            tone-mapped sRGB image (default sss_render.png)
  --linear F.pfm            linear outgoing radiance Lo (eq. 14) per pixel, RGB float,
                            no tone mapping, ambient or specular; background 0
  --bake F.ply              each point's position (double), normal (float nx, ny, nz) and
                            outgoing radiance towards the camera (float red, green, blue), in
                            input order, finite points only
  --stats F.json            time of each step, counts and every setting used
  --material NAME           measured preset (default )" << sss::kDefaultPreset << R"(), one of)" << preset_list(28) << R"(
  --sigma-a R,G,B           custom absorption, 1/mm (with --sigma-s; replaces --material)
  --sigma-s R,G,B           custom reduced scattering sigma_s', 1/mm
  --eta V                   relative index of refraction (default )" << sss::kDefaultEta << R"()
  --mm-per-unit MM          millimetres per scene unit (default 1; 1000 for scans in metres)
  --scale MM                the same as --mm-per-unit (its older name)
  --light-dir X,Y,Z         from the object towards a directional light; repeatable, up to 5
                            (default one light at -0.3,0.5,0.8)
  --point-light X,Y,Z       a point light at X,Y,Z (scene units), as a positional vtkLight
                            with no spot cone; repeatable, up to 5 lights in all
  --light-attenuation A,B,C point lights' irradiance over A + B d + C d^2, d in scene units
                            (default 1,0,0: none, as VTK's; 0,0,1: the inverse square)
  --light-irradiance V      irradiance of each light (default 1)
  --view-dir X,Y,Z          from the object towards the camera (default 0,-1,0.6)
  --up X,Y,Z                camera up (default 0,0,1)
  --ortho                   orthographic camera (default perspective, 30 degree view angle)
  --fit surface|all         the camera's frame holds 99 % of the points, centred on them
                            (surface, default: stray returns and a scan's far rows do not
                            shrink the surface), or every point (all: VTK's ResetCamera)
  --size WxH                image size in pixels (default 512x512)
  --method gpu|reference    gpu (default): the real-time method; reference: the CPU
                            evaluation of the same model at full precision (progress on
                            stderr), shown the same way
  --backend osmesa|egl|x    OpenGL context: OSMesa or EGL (no display needed; default egl)
                            or an X window (needs DISPLAY); --stats names the renderer
  --gpu N|surfaceless       egl: draw on EGL device N (0, 1, ...), or on Mesa's surfaceless
                            platform (default: the first graphics card, else Mesa's software
                            device, else the surfaceless platform; SSS_EGL_DEVICE=N does the
                            same for scripts)
  --quality NAME            interactive, balanced (default) or accurate: named settings of
                            the flags below, which override it (docs/benchmark/bench.md)
  --strategy NAME           near-far (default): each surfel's cell lit through the light
                            map, near field from a table of weights, far field by a walk of
                            the lit cells; paper: 49 Gaussian taps in a 40x40 window of a
                            512x512 map at 64^3 grid points (the 2005 paper's method)
  --max-map N               largest light-map side, texels (default )" << pass->GetMaxMapSize() << R"()
  --texel-per-radius V      light-map texel over the disc radius (default )" << pass->GetTexelPerRadius() << R"()
  --cell-samples N          points per surfel cell whose light the map is asked for
                            (default )" << pass->GetCellSamples() << R"()
  --opening-angle V         far-field walk: a group of cells counts as one source below this
                            size over distance, smaller is finer, 0.05 to 2 (default )" << pass->GetOpeningAngle() << R"()
  --group-lengths V         far-field walk: largest source group, in diffusion lengths 1/s_tr
                            of the channels that still matter (default )" << pass->GetMaxGroupDiffusionLengths() << R"()
  --grid-level K            paper: 2^K grid points per axis (default 0: the paper's 64)
  --exposure V              PNG tone mapping: sRGB(clamp(V * Lo)) (default 0: automatic,
                            the 99.5th percentile of the visible Lo maps to white)
  --radius-scale F          multiplies the disc radius that closes the surface (default 1)
  --coverage F              the surface fraction that radius may leave uncovered, measured on
                            each point's Voronoi cell in its tangent plane (default 1e-4)
  --radius-mode M           automatic (default: one radius per point where the local spacing
                            spreads, p90/p10 above 1.6, as in scans whose density falls with
                            range), uniform, or per-point
  --splatting M             blended (default: overlapping discs blended with Gaussian weights)
                            or discs (hard discs)
  --samples N               for a PLY or OBJ mesh: N points sampled uniformly on its surface
                            instead of its vertices, as pcl_mesh_sampling does (default 0:
                            vertices)
  --isolated RATIO|keep     leave out points whose mean distance to their 16 nearest exceeds
                            RATIO times that of those neighbours (default 5: stray returns,
                            flying pixels; the shared scans' own surfaces reach 3.0); keep:
                            none left out
  --denoise on|off          on (default): each point moved onto the smooth surface fitted to
                            its neighbours over a neighbourhood sized from the depth noise
                            measured there, normals (when estimated) from that surface, so a
                            scan shows its surface, not its noise; off: the points as given,
                            normals fitted over 3 mean spacings (--stats: measured_surface)
  --memory-cap MIB          largest memory a file or --samples may claim; a header that
                            claims more, or more data than the file holds, is refused before
                            anything is read (default: half the physical memory)
  --frames N                after the outputs, time N frames with the camera orbiting (light
                            static), N with the light moving, and N of plain VTK points
                            (vertex cells, point size 2) of the same cloud (default 0)
  --help                    this text
)";
  return text.str();
}

void apply_pass_settings(const Options& o, vtkSubsurfacePass* pass) {
  if (o.quality) pass->SetQualityPreset(*o.quality);
  if (o.strategy) pass->SetKernelStrategyByName(*o.strategy);
  if (o.grid_level) pass->SetGridLevel(*o.grid_level);
  if (o.max_map_size) pass->SetMaxMapSize(*o.max_map_size);
  if (o.texel_per_radius) pass->SetTexelPerRadius(*o.texel_per_radius);
  if (o.cell_samples) pass->SetCellSamples(*o.cell_samples);
  if (o.opening_angle) pass->SetOpeningAngle(*o.opening_angle);
  if (o.group_diffusion_lengths) pass->SetMaxGroupDiffusionLengths(*o.group_diffusion_lengths);
}

std::string apply_splat_radii(const Options& o, SurfelCloud& cloud) {
  const SplatRadiusMode mode = o.radius_mode == "uniform"     ? SplatRadiusMode::Uniform
                               : o.radius_mode == "per-point" ? SplatRadiusMode::PerPoint
                                                              : SplatRadiusMode::Automatic;
  const SplatRadii radii = assign_splat_radii(cloud, mode, o.coverage_target, o.radius_scale);
  std::ostringstream line;
  line << "view: " << (radii.per_point_chosen() ? "one disc radius per point, median " : "disc radius ")
       << radii.view_radius;
  if (!radii.per_point_chosen()) line << " (uncovered " << 100.0 * radii.view_uncovered << " %)";
  line << " (light maps too); cells' radius " << radii.radius << "; local spacing spread "
       << radii.spacing_spread;
  return line.str();
}

Options parse(int argc, char** argv) {
  Options o;
  vtkNew<vtkSubsurfacePass> limits;  // the settings' ranges
  for (Arguments args(argc, argv); args.next();) {
    const std::string& flag = args.flag();
    const auto value = [&args] { return args.value(); };
    if (flag == "--help" || flag == "-h") {
      o.help = true;
    } else if (flag == "--output") {
      o.output_png = value();
    } else if (flag == "--linear") {
      o.linear_pfm = value();
    } else if (flag == "--stats") {
      o.stats_json = value();
    } else if (flag == "--material") {
      o.material = value();
    } else if (flag == "--sigma-a") {
      const auto v = numbers(flag, value(), 3);
      o.sigma_a = {v[0], v[1], v[2]};
      o.custom_material = true;
    } else if (flag == "--sigma-s") {
      const auto v = numbers(flag, value(), 3);
      o.sigma_s = {v[0], v[1], v[2]};
      o.custom_material = true;
    } else if (flag == "--eta") {
      o.eta = number(flag, value());
    } else if (flag == "--mm-per-unit" || flag == "--scale") {
      o.mm_per_unit = number(flag, value());
    } else if (flag == "--light-dir") {
      o.light_dirs.push_back(direction(flag, value()));
    } else if (flag == "--point-light") {
      const auto v = numbers(flag, value(), 3);
      o.point_lights.emplace_back(v[0], v[1], v[2]);
    } else if (flag == "--light-attenuation") {
      const auto v = numbers(flag, value(), 3);
      o.light_attenuation = Eigen::Vector3d(v[0], v[1], v[2]);
      if (o.light_attenuation.minCoeff() < 0.0 || !(o.light_attenuation.sum() > 0.0))
        throw std::invalid_argument(flag + ": needs three values >= 0, not all 0");
    } else if (flag == "--light-irradiance") {
      o.light_irradiance = number(flag, value());
    } else if (flag == "--view-dir") {
      o.view_dir = direction(flag, value());
    } else if (flag == "--up") {
      o.up = direction(flag, value());
    } else if (flag == "--size") {
      const std::string text = value();
      const auto x = text.find('x');
      if (x == std::string::npos) throw std::invalid_argument("--size: '" + text + "' is not WxH");
      const double w = number(flag, text.substr(0, x)), h = number(flag, text.substr(x + 1));
      if (w < 1 || h < 1 || w > 16384 || h > 16384 || w != std::floor(w) || h != std::floor(h))
        throw std::invalid_argument("--size: '" + text + "' needs whole sizes from 1 to 16384");
      o.width = static_cast<int>(w);
      o.height = static_cast<int>(h);
    } else if (flag == "--method") {
      o.method = value();
      if (o.method != "reference" && o.method != "gpu")
        throw std::invalid_argument("--method: '" + o.method + "' is not gpu or reference");
    } else if (flag == "--backend") {
      o.backend = value();
      if (o.backend != "osmesa" && o.backend != "egl" && o.backend != "x")
        throw std::invalid_argument("--backend: '" + o.backend + "' is not osmesa, egl or x");
    } else if (flag == "--gpu") {
      const std::string device = value();
      o.gpu = device == "surfaceless" ? kSurfacelessPlatform : whole(flag, device, 0, 1023);
    } else if (flag == "--quality") {
      o.quality = value();
      try {
        QualitySettings::preset(*o.quality);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string("--quality: ") + e.what());
      }
    } else if (flag == "--strategy") {
      o.strategy = value();
      if (!limits->SetKernelStrategyByName(*o.strategy))
        throw std::invalid_argument("--strategy: '" + *o.strategy + "' is not near-far or paper");
    } else if (flag == "--bake") {
      o.bake_ply = value();
    } else if (flag == "--ortho") {
      o.ortho = true;
    } else if (flag == "--fit") {
      o.fit_all = fit_all(flag, value());
    } else if (flag == "--isolated") {
      o.isolation_ratio = isolation_ratio(flag, value());
    } else if (flag == "--denoise") {
      o.denoise = on_off(flag, value());
    } else if (flag == "--grid-level") {
      o.grid_level = whole(flag, value(), 0, 10);
    } else if (flag == "--max-map") {
      o.max_map_size =
          whole(flag, value(), limits->GetMaxMapSizeMinValue(), limits->GetMaxMapSizeMaxValue());
    } else if (flag == "--cell-samples") {
      o.cell_samples =
          whole(flag, value(), limits->GetCellSamplesMinValue(), limits->GetCellSamplesMaxValue());
    } else if (flag == "--texel-per-radius") {
      o.texel_per_radius = within(flag, number(flag, value()), limits->GetTexelPerRadiusMinValue(),
                                  limits->GetTexelPerRadiusMaxValue());
    } else if (flag == "--opening-angle") {
      o.opening_angle = within(flag, number(flag, value()), limits->GetOpeningAngleMinValue(),
                               limits->GetOpeningAngleMaxValue());
    } else if (flag == "--radius-scale") {
      o.radius_scale = number(flag, value());
      if (o.radius_scale <= 0 || o.radius_scale > 10)
        throw std::invalid_argument("--radius-scale: needs a value in (0, 10]");
    } else if (flag == "--coverage") {
      o.coverage_target = number(flag, value());
      if (!(o.coverage_target >= 0.0 && o.coverage_target <= 0.5))
        throw std::invalid_argument("--coverage: needs an uncovered fraction from 0 to 0.5");
    } else if (flag == "--radius-mode") {
      o.radius_mode = value();
      if (o.radius_mode != "automatic" && o.radius_mode != "uniform" && o.radius_mode != "per-point")
        throw std::invalid_argument("--radius-mode: needs automatic, uniform or per-point, not '" +
                                    o.radius_mode + "'");
    } else if (flag == "--splatting") {
      o.splatting = value();
      if (o.splatting != "blended" && o.splatting != "discs")
        throw std::invalid_argument("--splatting: needs blended or discs, not '" + o.splatting + "'");
    } else if (flag == "--samples") {
      o.mesh_samples = count(flag, value(), 1e9);
    } else if (flag == "--memory-cap") {
      o.memory_cap = memory_cap(flag, value());
    } else if (flag == "--frames") {
      const double n = number(flag, value());
      if (n < 0 || n > 100000 || n != std::floor(n))
        throw std::invalid_argument("--frames: needs a whole number from 0 to 100000");
      o.frames = static_cast<int>(n);
    } else if (flag == "--group-lengths") {
      o.group_diffusion_lengths = number(flag, value());
      if (*o.group_diffusion_lengths < 0.1)
        throw std::invalid_argument("--group-lengths: needs a value of at least 0.1");
    } else if (flag == "--exposure") {
      o.exposure = number(flag, value());
      if (o.exposure < 0) throw std::invalid_argument("--exposure: must be >= 0");
    } else if (!flag.empty() && flag[0] == '-') {
      throw std::invalid_argument(flag + ": unknown flag (see --help)");
    } else if (o.input.empty()) {
      o.input = flag;
    } else {
      throw std::invalid_argument("'" + flag + "': only one input file can be given");
    }
  }
  if (o.light_dirs.empty() && o.point_lights.empty()) o.light_dirs.emplace_back(-0.3, 0.5, 0.8);
  const int most = vtkSubsurfacePass::GetMaxLights();
  if (o.light_dirs.size() + o.point_lights.size() > static_cast<std::size_t>(most))
    throw std::invalid_argument("--light-dir, --point-light: at most " + std::to_string(most) +
                                " lights are supported");
  return o;
}

bool fit_all(const std::string& flag, const std::string& text) {
  if (text != "surface" && text != "all")
    throw std::invalid_argument(flag + ": needs surface or all, not '" + text + "'");
  return text == "all";
}

bool on_off(const std::string& flag, const std::string& text) {
  if (text != "on" && text != "off")
    throw std::invalid_argument(flag + ": needs on or off, not '" + text + "'");
  return text == "on";
}

double isolation_ratio(const std::string& flag, const std::string& text) {
  if (text == "keep") return 0.0;
  const double ratio = number(flag, text);
  if (!(ratio > 1.0 && ratio <= 1e6))
    throw std::invalid_argument(flag + ": needs a ratio above 1 (up to 1e6) or keep");
  return ratio;
}

std::vector<Light> lights_of(const Options& o, const Eigen::Vector3d& centre) {
  std::vector<Light> lights;
  for (const auto& d : o.light_dirs) lights.push_back({d, o.light_irradiance});
  for (const auto& p : o.point_lights) {
    Light light;
    light.positional = true;
    light.position = p;
    light.direction = (p - centre).norm() > 0.0 ? Eigen::Vector3d((p - centre).normalized())
                                                : Eigen::Vector3d::UnitZ();
    light.attenuation = o.light_attenuation;
    light.irradiance = o.light_irradiance;
    lights.push_back(light);
  }
  return lights;
}

}  // namespace sss::cli
