// Optical coefficients of a translucent material (Jensen et al. 2001, table of measured media).
#pragma once

#include <array>
#include <string>
#include <vector>

namespace sss {

using Rgb = std::array<double, 3>;

struct Material {
  std::string name = "custom";
  Rgb sigma_a{};        // absorption coefficient, 1/mm
  Rgb sigma_s_prime{};  // reduced scattering coefficient, 1/mm
  Rgb eta{1.3, 1.3, 1.3};  // relative index of refraction
  double mm_per_unit = 1.0;  // millimetres per scene unit (1000 for a scan in metres)

  // Throws std::invalid_argument naming the first bad value (negative, NaN, eta <= 0,
  // sigma_t' = 0, scale <= 0).
  void validate() const;

  // One of the 12 measured presets by name (apple, chicken1, chicken2, cream, ketchup,
  // marble, potato, skimmilk, skin1, skin2, spectralon, wholemilk); eta 1.3 unless given.
  // Throws std::invalid_argument listing the known names for an unknown one.
  static Material preset(const std::string& name, double eta = 1.3, double mm_per_unit = 1.0);
  static Material custom(const Rgb& sigma_a, const Rgb& sigma_s_prime, double eta,
                         double mm_per_unit = 1.0);
  static std::vector<std::string> preset_names();
};

}  // namespace sss
