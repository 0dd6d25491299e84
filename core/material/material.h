// Optical coefficients of a translucent material (Jensen et al. 2001, table of measured media).
#pragma once

#include <array>
#include <string>
#include <vector>

namespace sss {

using Rgb = std::array<double, 3>;

// The default preset's name (kDefaultPreset) and eta (kDefaultEta), from the presets' one home.
#define SSS_PRESET(name, sr, sg, sb, ar, ag, ab)
#define SSS_DEFAULT_PRESET(name) inline constexpr const char* kDefaultPreset = #name;
#define SSS_DEFAULT_ETA(value) inline constexpr double kDefaultEta = value;
#include "material_presets.def"
#undef SSS_PRESET
#undef SSS_DEFAULT_PRESET
#undef SSS_DEFAULT_ETA

struct Material {
  std::string name = "custom";
  Rgb sigma_a{};        // absorption coefficient, 1/mm
  Rgb sigma_s_prime{};  // reduced scattering coefficient, 1/mm
  Rgb eta{kDefaultEta, kDefaultEta, kDefaultEta};  // relative index of refraction
  double mm_per_unit = 1.0;  // millimetres per scene unit (1000 for a scan in metres)

  // Throws std::invalid_argument naming the first bad value (negative, NaN, eta <= 0,
  // sigma_t' = 0, scale <= 0).
  void validate() const;

  // One of the 12 measured presets of material_presets.def by name (apple, chicken1, chicken2,
  // cream, ketchup, marble, potato, skimmilk, skin1, skin2, spectralon, wholemilk).
  // Throws std::invalid_argument listing the known names for an unknown one.
  static Material preset(const std::string& name, double eta = kDefaultEta,
                         double mm_per_unit = 1.0);
  static Material custom(const Rgb& sigma_a, const Rgb& sigma_s_prime, double eta,
                         double mm_per_unit = 1.0);
  static std::vector<std::string> preset_names();
};

}  // namespace sss
