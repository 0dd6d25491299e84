// Fresnel terms at a smooth dielectric boundary between air and a medium of relative index eta.
#pragma once

namespace sss {

// Exact reflectance for unpolarised light arriving from air at angle acos(cos_theta) to the
// normal (|cos_theta| is used). Total internal reflection (possible when eta < 1) returns 1.
double fresnel_reflectance(double eta, double cos_theta);

// Ft = 1 - Fr (eq. 14, 15).
inline double fresnel_transmittance(double eta, double cos_theta) {
  return 1.0 - fresnel_reflectance(eta, cos_theta);
}

// Diffuse Fresnel reflectance Fdr (eq. 11): Jensen's fit for eta >= 1,
// Egan and Hilgeman's fit for eta < 1.
double diffuse_fresnel_reflectance(double eta);

}  // namespace sss
