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

// Jensen et al. 2001, measured sigma_s' and sigma_a in 1/mm (R, G, B).
const PresetRow kPresets[] = {
    {"apple", {2.29, 2.39, 1.97}, {0.0030, 0.0034, 0.046}},
    {"chicken1", {0.15, 0.21, 0.38}, {0.015, 0.077, 0.19}},
    {"chicken2", {0.19, 0.25, 0.32}, {0.018, 0.088, 0.20}},
    {"cream", {7.38, 5.47, 3.15}, {0.0002, 0.0028, 0.0163}},
    {"ketchup", {0.18, 0.07, 0.03}, {0.061, 0.97, 1.45}},
    {"marble", {2.19, 2.62, 3.00}, {0.0021, 0.0041, 0.0071}},
    {"potato", {0.68, 0.70, 0.55}, {0.0024, 0.0090, 0.12}},
    {"skimmilk", {0.70, 1.22, 1.90}, {0.0014, 0.0025, 0.0142}},
    {"skin1", {0.74, 0.88, 1.01}, {0.032, 0.17, 0.48}},
    {"skin2", {1.09, 1.59, 1.79}, {0.013, 0.070, 0.145}},
    {"spectralon", {11.6, 20.4, 14.9}, {0.0, 0.0, 0.0}},
    {"wholemilk", {2.55, 3.21, 3.77}, {0.0011, 0.0024, 0.014}},
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
