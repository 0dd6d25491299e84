// The area each surfel stands for (dA of eq. 16): its cell, the part of its tangent plane within
// its disc (LocalSurfels::disc_radius: the radius that closes the surface, at least the cells'
// radius) that lies nearer to it than to any other surfel of the same surface (a Voronoi cell
// clipped to the disc, cell_polygon.h). Cells tile the sampled surface whatever the sampling
// (regular, random, or thinning with range as a scanner sees it), and stop where the discs stop
// covering it (an open edge, a hole). Each cell's outline is kept in its surfel's tangent frame
// (local_surface.h) for the near field (near_field.h).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "cancel.h"
#include "local_surfels.h"
#include "surfel_index.h"

namespace sss {

struct SurfelCells {
  std::vector<double> area;                  // mm^2
  std::vector<std::uint32_t> first;          // outline of cell j: [first[j], first[j + 1])
  std::vector<Eigen::Vector2d> outline;      // counter-clockwise, mm, in the surfel's frame
  std::size_t size() const { return area.size(); }
};

// The other surfel j belongs to surfel i's local surface when it lies within i's surface
// thickness of i's osculating paraboloid and its normal is within 60 degrees of i's (either
// orientation).
bool on_same_surface(const LocalSurfels& surfels, std::size_t i, std::size_t j, double thickness);

// The cells of every surfel (local_surfels must carry its surface fit). Throws Cancelled once
// `cancel` is set.
SurfelCells surfel_cells(const LocalSurfels& surfels, const SurfelIndex& index,
                         const CancelFlag* cancel = nullptr);

}  // namespace sss
