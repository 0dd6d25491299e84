// Step 2, second part: the near field of eq. 17 at each receiver, as weights on its
// neighbours' irradiance that the light does not change,
//   B_near(x_o) = 1/pi Sum_j w_oj E_j,
// over the surfels j within the reach (near_far_split.h). For those of the receiver's own
// surface, w_oj = the kernel, bent with the surface (radial_kernel.h), integrated exactly over
// j's cell (surfel_cells.h) projected into the receiver's tangent plane (cell_polygon.h): the
// near field is taken on the receiver's smooth local surface, not on the stack of discs, so
// scanner noise and the flat discs' overlap above a curved surface do not bias it. Where no
// disc covers the plane (an open edge, a hole), no cell does and no light enters. Surfels of
// other surfaces in reach (the far side of a thin part) weigh in with eq. 3 integrated exactly
// over their cell in its own plane (dipole_over). The far field sums the cells beyond the reach.
// Computed when the geometry or the material changes; a light move only re-weights it by the
// new E. Memory: one entry (source index and three weights) per neighbour in reach, about 30
// per receiver (16 bytes each on the GPU).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "dipole.h"
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

// Weights for `receivers` (indices into the surfels; empty: every surfel, in order) over the
// surfels within `reach` mm. Throws Cancelled once `cancel` is set.
NearFieldWeights near_field_weights(const LocalSurfels& surfels, const SurfelCells& cells,
                                    const SurfelIndex& index, const Dipole& dipole, double reach,
                                    const std::vector<std::size_t>& receivers = {},
                                    const CancelFlag* cancel = nullptr);

}  // namespace sss
