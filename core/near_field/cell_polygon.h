// A surfel's cell in a receiver's tangent plane as a convex polygon (its Voronoi cell among
// the surfels of that surface, within its disc), and the kernel integrated over it exactly:
// Integral_P K dA = Contour_P G(rho) dtheta (radial_kernel.h), the receiver at the origin,
// Gauss-Legendre along each edge (8 points where it is seen under a wide angle, else 2).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "material.h"
#include "radial_kernel.h"

namespace sss {

using Polygon = std::vector<Eigen::Vector2d>;  // counter-clockwise

// The disc of radius r around c as a 24-gon of the disc's area, into `polygon`.
void disc_polygon(const Eigen::Vector2d& c, double r, Polygon& polygon);

// Keeps the part where normal . x <= offset; `scratch` is reused storage.
void clip(Polygon& polygon, const Eigen::Vector2d& normal, double offset, Polygon& scratch);

// Keeps the part nearer to `own` than to `other` (their perpendicular bisector).
void clip_to_nearer(Polygon& polygon, const Eigen::Vector2d& own, const Eigen::Vector2d& other,
                    Polygon& scratch);

// The polygon's area, positive when its corners run counter-clockwise (the shoelace formula).
double signed_area(const Polygon& polygon);

// Integral over the polygon of K at distance rho from the origin, per channel.
Rgb kernel_over(const Polygon& polygon, const RadialKernel& kernel, double kappa);

// Integral of eq. 3 over a polygon of sources in their plane (normal out of the material) at a
// receiver `height` above that plane along the normal (the origin is the receiver's foot):
// G(rho) = Integral_0^rho Rd r dr in closed form, since with d^2 = r^2 + a^2,
// Integral z (1 + s d) e^(-s d) / d^3 r dr = -z e^(-s d) / d (a: the pole's height off the
// receiver; distances clamped at their planar minima as in DipoleChannel::Rd_from_distances).
Rgb dipole_over(const Polygon& polygon, const Dipole& dipole, double height);

}  // namespace sss
