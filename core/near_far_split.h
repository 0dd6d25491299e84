// Where the near field (on the receiver's local surface, near_field.h) hands over to the far
// field (the light's samples, source_tree.h or the GPU's virtual points): the kernel splits at
// r0 < r < r1 = 2 r0 by KernelWindow. When the kernel's support ends before r1, the near field
// takes all of it and there is no far field: a scene whose diffusion length is far below its
// surfel spacing needs nothing but each receiver's own surroundings.
#pragma once

#include "dipole.h"
#include "kernel_window.h"

namespace sss {

struct NearFarSplit {
  KernelWindow near;  // All (no far field) or Near(r0, r1)
  KernelWindow far;   // Far(r0, r1); unused without a far field
  double reach = 0;   // mm: the near field's outer radius (r1, or the support)
  bool has_far = false;

  // r0 = min_r0 (mm) unless the support of `kernel_tolerance` of the integral ends before
  // 2 min_r0. Throws std::invalid_argument for a min_r0 that is not finite and positive.
  static NearFarSplit choose(const Dipole& dipole, double min_r0, double kernel_tolerance);

  // The r0 the near field needs: one disc radius, so that the near field holds the receiver's
  // own disc, the discs stacked over it (scanner noise, a curved surface) and its nearest
  // neighbours' cells with their true shapes; farther surfels are the far field's sources,
  // each cell a patch of its area split near a receiver (source_tree.h).
  static double minimum_r0(double disc_radius);
};

}  // namespace sss
