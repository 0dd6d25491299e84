// Where the near field's table (near_field.h) hands over to the far field: a receiver's table
// holds whole the cells of the surfels within `reach` = two disc radii of it (the receiver's own
// disc, the discs stacked over it by scanner noise or a curved surface, and its neighbours'
// cells with their true shapes); the far field sums the cells beyond (source_tree.h on the
// CPU, far_field.glsl on the GPU). When the kernel's support ends within a disc radius of the
// reach, no cell beyond it matters and there is no far field: a scene whose diffusion length
// is far below its surfel spacing needs nothing but each receiver's own surroundings.
#pragma once

#include "dipole.h"

namespace sss {

struct NearFarSplit {
  double reach = 0;  // mm
  bool has_far = false;

  // Throws std::invalid_argument for a disc radius that is not finite and positive.
  static NearFarSplit choose(const Dipole& dipole, double disc_radius, double kernel_tolerance);
};

}  // namespace sss
