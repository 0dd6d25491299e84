// Step 2, second part: the near field of eq. 17 at each receiver, as weights on its
// neighbours' irradiance that the light does not change,
//   B_near(x_o) = 1/pi Sum_j w_oj E_j,
// w_oj = the near part of the kernel, bent with the surface (radial_kernel.h), integrated
// exactly over surfel j's cell (surfel_cells.h) projected into the receiver's tangent plane
// (cell_polygon.h).
// Where no disc covers the plane (an open edge, a hole), no cell does and no light enters.
// Surfels of other surfaces within the near reach (the far side of a thin part) weigh in with
// the near part of eq. 3 summed over 32 points of their cell (a disc of its area).
// With `whole_cells` (the GPU's table) every cell whose surfel lies within the reach weighs in
// with all of its kernel, and the far field sums the cells beyond the reach whole, with no
// window (far_field.glsl).
// Computed when the geometry or the material changes; a light move only re-weights it by the
// new E. Memory: one entry (source index and three weights) per neighbour in reach.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "dipole.h"
#include "kernel_window.h"
#include "local_surfels.h"
#include "material.h"
#include "surfel_cells.h"
#include "surfel_index.h"

namespace sss {

struct NearFieldWeights {
  // Row r (one per receiver asked for) holds entries [first[r], first[r + 1]).
  std::vector<std::uint32_t> first;
  std::vector<std::uint32_t> source;  // the surfel whose irradiance an entry weighs
  std::vector<Rgb> weight;            // Integral of the kept kernel over its part (no unit)
  std::size_t rows() const { return first.empty() ? 0 : first.size() - 1; }

  // 1/pi Sum w E over row r.
  Rgb B(std::size_t row, const std::vector<Rgb>& E) const;
};

// Weights for `receivers` (indices into the surfels; empty: every surfel, in order); `window`
// keeps the near part (All: the whole kernel) out to `reach` mm.
NearFieldWeights near_field_weights(const LocalSurfels& surfels, const SurfelCells& cells,
                                    const SurfelIndex& index, const Dipole& dipole,
                                    const KernelWindow& window, double reach,
                                    const std::vector<std::size_t>& receivers = {},
                                    bool whole_cells = false);

}  // namespace sss
