// Step 2, first part: each surfel's irradiance (eq. 15) averaged over its cell,
//   E_j = E_light albedo_j 1/S Sum_s Ft(eta, theta_s) cos(theta_s) V(y_s),
// over S points y_s spread evenly over a disc of the cell's area on the surfel's local
// surface (local_surface.h), theta_s from the surface's normal there, V(y_s) from the light's
// map (light_reaches). Shadow edges and the terminator are resolved below the surfel size:
// a surfel half in shadow gets half its light. Where the first S points disagree (an edge
// crosses the cell), the cell is sampled again with `refined` points. The side of a surfel
// the light sees is lit (scans may hold either orientation). This is the CPU form of
// shaders/lit_cells/surfel_irradiance_fs.glsl.
#pragma once

#include <vector>

#include "light_map.h"
#include "local_surfels.h"
#include "material.h"

namespace sss {

// E per light and surfel: E[l][j], per mm^2 of surface.
using SurfelIrradiance = std::vector<std::vector<Rgb>>;

// `area` from surfel_cells; `samples` >= 1 points per cell, `refined` >= samples where they
// disagree. Throws std::invalid_argument for sizes that differ or too few samples.
SurfelIrradiance surfel_irradiance(const LocalSurfels& surfels, const std::vector<double>& area,
                                   const Material& material, const LightMaps& light,
                                   int samples, int refined);

// The sum over the lights, for `surfels` surfels (zero without lights).
std::vector<Rgb> total_irradiance(const SurfelIrradiance& E, std::size_t surfels);

// The fraction in [0, 1) that turns surfel `index`'s sample pattern, the same on the GPU.
double pattern_rotation(std::size_t index);

}  // namespace sss
