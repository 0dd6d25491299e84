// The near field of eq. 17 at a receiver, integrated on its local surface (local_surface.h):
//   B_near(x_o) = 1/pi Sum_q W_q C_q E(y_q),   E(y) = E_light Ft(eta, theta) cos(theta) albedo V(y)
// over the nodes y_q of a NearFieldQuadrature laid out on the receiver's osculating paraboloid,
// each node's cosine from the paraboloid's normal there; C_q = Rd(y_q, n_q -> x_o) / Rd(rho_q)
// bends the ring's planar weight with the surface (eq. 3 from the node's point and normal, as
// the far field evaluates its sources), so the split radius does not change B. V(y) = 1 where the local surface of
// the disc the light's map sees at y's texel passes within visibility_tolerance of y along
// the light (the receiver's surface_thickness): the same surface.
// A point seen in front of it shadows the node; nothing there, or only something behind it,
// means the surface ends (an open edge, a hole): no light enters. The albedo is that of the
// disc the light sees. This is the CPU form of shaders/near_field.glsl.
#pragma once

#include <cstddef>
#include <vector>

#include "illumination.h"
#include "local_surfels.h"
#include "material.h"
#include "near_field_quadrature.h"

namespace sss {

struct NearFieldSettings {
  QuadratureSettings quadrature;
};

class NearField {
 public:
  // `light` is the illumination map of the same surfels (illuminate); the quadrature covers
  // the near part of the kernel that `window` keeps, out to `reach` mm.
  NearField(const LocalSurfels& surfels, const Material& material,
            const IlluminationSamples& light, const KernelWindow& window, double reach,
            const NearFieldSettings& settings);

  // Near part of B (eq. 17) at surfel `receiver` (index into the surfels).
  Rgb B(std::size_t receiver) const;

  const NearFieldQuadrature& quadrature() const { return quadrature_; }

 private:
  const LocalSurfels& surfels_;
  const IlluminationSamples& light_;
  Material material_;
  Dipole dipole_;
  NearFieldQuadrature quadrature_;
  double kappa_limit_ = 0.0;
};

}  // namespace sss
