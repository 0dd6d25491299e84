// The CPU form of the grid method: B (eq. 17) at the pruned virtual points, interpolated
// trilinearly at every surfel. With a near field, the grid carries only the smooth far part
// of the kernel (KernelWindow) and each surfel adds its own near part from the sources.
#pragma once

#include "reference_renderer.h"
#include "virtual_grid.h"

namespace sss {

struct GridSettings {
  IlluminationSettings illumination;
  SourceTreeSettings tree;
  VirtualGridSettings grid;
  // Near-field radius in grid spacings: the kernel is split between r0 = near_field_cells * h
  // and r1 = 2 r0. 0 is the paper's method: all of B comes from the grid.
  double near_field_cells = 2.0;
  Progress progress;
};

SurfelRadiance render_grid(const SurfelCloud& cloud, const Material& material,
                           const std::vector<DirectionalLight>& lights,
                           const GridSettings& settings = {});

}  // namespace sss
