// Splits the dipole kernel by distance into a near part (kept per receiver) and a smooth far
// part (carried by the virtual grid): Rd = Rd * (1 - w) + Rd * w, w rising from 0 at r0 to 1
// at r1 as a quintic smoothstep (C2, so the far part stays smooth enough to interpolate).
#pragma once

namespace sss {

struct KernelWindow {
  enum class Part { All, Near, Far };
  Part part = Part::All;
  double r0 = 0.0;  // mm
  double r1 = 0.0;  // mm, > r0 for Near and Far

  static KernelWindow all() { return {}; }
  static KernelWindow near(double r0, double r1) { return {Part::Near, r0, r1}; }
  static KernelWindow far(double r0, double r1) { return {Part::Far, r0, r1}; }

  // Fraction of Rd this part keeps at distance r.
  double weight(double r) const {
    if (part == Part::All) return 1.0;
    const double t = r <= r0 ? 0.0 : (r >= r1 ? 1.0 : (r - r0) / (r1 - r0));
    const double far = t * t * t * (t * (6.0 * t - 15.0) + 10.0);
    return part == Part::Far ? far : 1.0 - far;
  }
};

}  // namespace sss
