#include "material.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace sss {
namespace {

struct PresetRow {
  const char* name;
  Rgb sigma_s_prime;
  Rgb sigma_a;
};

const PresetRow kPresets[] = {
#define SSS_PRESET(name, sr, sg, sb, ar, ag, ab) {#name, {sr, sg, sb}, {ar, ag, ab}},
#define SSS_DEFAULT_PRESET(name)
#define SSS_DEFAULT_ETA(value)
#include "material_presets.def"
#undef SSS_PRESET
#undef SSS_DEFAULT_PRESET
#undef SSS_DEFAULT_ETA
};

const char* kChannel[] = {"red", "green", "blue"};

[[noreturn]] void refuse(const std::string& what, double value, const std::string& rule) {
  std::ostringstream msg;
  msg << "[sss::Material] " << what << " = " << value << ": " << rule;
  throw std::invalid_argument(msg.str());
}

}  // namespace

void Material::validate() const {
  for (int c = 0; c < 3; ++c) {
    const std::string ch = kChannel[c];
    if (!std::isfinite(sigma_a[c]) || sigma_a[c] < 0.0)
      refuse("sigma_a " + ch, sigma_a[c], "must be finite and >= 0 (1/mm)");
    if (!std::isfinite(sigma_s_prime[c]) || sigma_s_prime[c] < 0.0)
      refuse("sigma_s' " + ch, sigma_s_prime[c], "must be finite and >= 0 (1/mm)");
    if (!(sigma_a[c] + sigma_s_prime[c] > 0.0))
      refuse("sigma_t' " + ch, sigma_a[c] + sigma_s_prime[c],
             "must be > 0: a medium that neither absorbs nor scatters has no diffusion");
    if (!std::isfinite(eta[c]) || eta[c] <= 0.0)
      refuse("eta " + ch, eta[c], "must be finite and > 0");
  }
  if (!std::isfinite(mm_per_unit) || mm_per_unit <= 0.0)
    refuse("mm_per_unit", mm_per_unit, "must be finite and > 0");
}

Material Material::preset(const std::string& name, double eta, double mm_per_unit) {
  for (const PresetRow& row : kPresets) {
    if (name == row.name) {
      Material m;
      m.name = row.name;
      m.sigma_a = row.sigma_a;
      m.sigma_s_prime = row.sigma_s_prime;
      m.eta = {eta, eta, eta};
      m.mm_per_unit = mm_per_unit;
      m.validate();
      return m;
    }
  }
  std::ostringstream msg;
  msg << "[sss::Material] unknown material '" << name << "'; known:";
  for (const PresetRow& row : kPresets) msg << ' ' << row.name;
  throw std::invalid_argument(msg.str());
}

Material Material::custom(const Rgb& sigma_a, const Rgb& sigma_s_prime, double eta,
                          double mm_per_unit) {
  Material m;
  m.sigma_a = sigma_a;
  m.sigma_s_prime = sigma_s_prime;
  m.eta = {eta, eta, eta};
  m.mm_per_unit = mm_per_unit;
  m.validate();
  return m;
}

std::vector<std::string> Material::preset_names() {
  std::vector<std::string> names;
  for (const PresetRow& row : kPresets) names.emplace_back(row.name);
  return names;
}

}  // namespace sss
