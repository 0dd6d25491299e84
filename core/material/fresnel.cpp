#include "fresnel.h"

#include <algorithm>
#include <cmath>

namespace sss {

double fresnel_reflectance(double eta, double cos_theta) {
  if (eta == 1.0) return 0.0;  // no boundary (the formula below is 0/0 at grazing)
  const double cos_i = std::min(1.0, std::fabs(cos_theta));
  const double sin2_t = (1.0 - cos_i * cos_i) / (eta * eta);  // Snell
  if (sin2_t >= 1.0) return 1.0;
  const double cos_t = std::sqrt(1.0 - sin2_t);
  const double r_s = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  const double r_p = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  return 0.5 * (r_s * r_s + r_p * r_p);
}

double diffuse_fresnel_reflectance(double eta) {
  if (eta >= 1.0) return -1.440 / (eta * eta) + 0.710 / eta + 0.668 + 0.0636 * eta;
  return -0.4399 + 0.7099 / eta - 0.3319 / (eta * eta) + 0.0636 / (eta * eta * eta);
}

}  // namespace sss
