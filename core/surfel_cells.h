// The area each surfel stands for (dA of eq. 16): its cell, the part of its local surface
// (local_surface.h) within its disc radius that lies nearer to it than to any other surfel of
// the same surface. Cells tile the sampled surface whatever the sampling (regular, random, or
// thinning with range as a scanner sees it), and stop where the discs stop covering it (an
// open edge, a hole). Measured by 64 points spread evenly over each disc.
#pragma once

#include <vector>

#include "local_surfels.h"
#include "surfel_index.h"

namespace sss {

// The other surfel j belongs to surfel i's local surface when it lies within i's surface
// thickness of i's osculating paraboloid and its normal is within 60 degrees of i's (either
// orientation).
bool on_same_surface(const LocalSurfels& surfels, std::size_t i, std::size_t j, double thickness);

// Cell areas in mm^2 (local_surfels must carry its surface fit).
std::vector<double> cell_areas(const LocalSurfels& surfels, const SurfelIndex& index);

}  // namespace sss
