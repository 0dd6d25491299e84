#include "cli_options.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace sss::cli {
namespace {

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

Eigen::Vector3d direction(const std::string& flag, const std::string& text) {
  const auto v = numbers(flag, text, 3);
  const Eigen::Vector3d d(v[0], v[1], v[2]);
  if (d.norm() == 0.0) throw std::invalid_argument(flag + ": the direction must not be zero");
  return d;
}

}  // namespace

std::string usage() {
  return R"(sss_render: renders a surfel cloud as a translucent material (dipole diffusion, Jensen 2001)
on the CPU, to PNG (tone-mapped sRGB) and optionally linear radiance (PFM) and JSON stats.

usage: sss_render [options]        (no input: a procedural torus the project generates)

  --output F.png            tone-mapped sRGB image (default sss_render.png)
  --linear F.pfm            linear outgoing radiance Lo (eq. 14), RGB float, background 0
  --stats F.json            timings, counts and every setting used
  --material NAME           measured preset (default marble): apple chicken1 chicken2 cream
                            ketchup marble potato skimmilk skin1 skin2 spectralon wholemilk
  --sigma-a R,G,B           custom absorption, 1/mm (with --sigma-s; replaces --material)
  --sigma-s R,G,B           custom reduced scattering sigma_s', 1/mm
  --eta V                   relative index of refraction (default 1.3)
  --scale MM_PER_UNIT       millimetres per scene unit (default 1; the demo shape is in mm)
  --light-dir X,Y,Z         from the object towards a directional light; repeatable
                            (default one light at -0.3,0.5,0.8)
  --light-irradiance V      irradiance of each light (default 1)
  --view-dir X,Y,Z          from the object towards the camera (default 0,-1,0.6)
  --up X,Y,Z                camera up (default 0,0,1)
  --size WxH                image size in pixels (default 512x512)
  --method reference|grid   reference: full per-point evaluation of eq. 16 (default);
                            grid: virtual points with trilinear interpolation (CPU form)
  --texel-per-zr V          illumination-map texel over the smallest z_r (default 0.25)
  --help                    this text
)";
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(flag + ": needs a value");
      return argv[++i];
    };
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
    } else if (flag == "--scale") {
      o.scale = number(flag, value());
    } else if (flag == "--light-dir") {
      o.light_dirs.push_back(direction(flag, value()));
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
      if (o.method != "reference" && o.method != "grid")
        throw std::invalid_argument("--method: '" + o.method + "' is not reference or grid");
    } else if (flag == "--texel-per-zr") {
      o.texel_per_z_r = number(flag, value());
    } else if (!flag.empty() && flag[0] == '-') {
      throw std::invalid_argument(flag + ": unknown flag (see --help)");
    } else {
      throw std::invalid_argument("'" + flag + "': reading clouds from files comes with the PCL "
                                  "loader; this build renders the procedural demo shape only");
    }
  }
  if (o.light_dirs.empty()) o.light_dirs.emplace_back(-0.3, 0.5, 0.8);
  return o;
}

}  // namespace sss::cli
