// The near field of eq. 17 at a receiver, integrated on its local surface (local_surface.h):
//   B_near(x_o) = 1/pi Sum_q W_q E(y_q),   E(y) = E_light Ft(eta, theta) cos(theta) albedo V(y)
// over the nodes y_q of a NearFieldQuadrature laid out on the receiver's osculating paraboloid,
// each node's cosine from the paraboloid's normal there. V(y) = 1 where the light's map sees,
// at y's texel, a point within visibility_tolerance of y along the light: the same surface.
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
  // An occluder must stand this many disc radii off the local surface to shadow it: flat discs
  // stack above a curved surface by up to kappa r^2 / 2, and scanner noise stacks them more.
  double occluder_height_in_radii = 1.0;
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
  NearFieldQuadrature quadrature_;
  double occluder_height_ = 0.0;
  double kappa_limit_ = 0.0;
};

}  // namespace sss
