// The bake's CPU steps (the cells, the near-field table's weights) stop when asked from another
// thread (core/support/cancel.h): with the flag set they throw Cancelled, without it they give
// the same result as without a flag.
#include <gtest/gtest.h>

#include "cancel.h"
#include "dipole.h"
#include "local_surfels.h"
#include "material.h"
#include "near_field.h"
#include "procedural_shapes.h"
#include "surfel_cells.h"

namespace sss {
namespace {

TEST(Cancel, CellsAndNearFieldWeightsStopWhenAsked) {
  const LocalSurfels sphere = LocalSurfels::from(make_sphere(10.0, 0.5), 1.0);
  const SurfelIndex index(sphere.positions);
  const Dipole dipole(Material::preset("marble"));
  const double reach = 2.0;
  CancelFlag cancel{false};
  const SurfelCells cells = surfel_cells(sphere, index, &cancel);
  const NearFieldWeights weights = near_field_weights(sphere, cells, index, dipole, reach, {},
                                                      &cancel);
  EXPECT_EQ(cells.outline.size(), surfel_cells(sphere, index).outline.size());
  EXPECT_EQ(weights.source, near_field_weights(sphere, cells, index, dipole, reach).source);
  cancel = true;
  EXPECT_THROW(surfel_cells(sphere, index, &cancel), Cancelled);
  EXPECT_THROW(near_field_weights(sphere, cells, index, dipole, reach, {}, &cancel), Cancelled);
}

}  // namespace
}  // namespace sss
