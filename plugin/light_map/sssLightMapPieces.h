// Step 1 over a cloud split into pieces (vtkSubsurfacePieces): each directional light's map is
// fitted over all pieces, in world millimetres, so that the pieces' texels coincide; then each
// texel keeps the surface nearest the light over all pieces, and where another piece's is
// nearer, this piece's texel becomes shadow (kForeignSurfel, light_visibility.glsl).
#ifndef sssLightMapPieces_h
#define sssLightMapPieces_h

#include "disc_raster.h"

#include <Eigen/Core>
#include <vector>

class vtkSubsurfacePieces;

namespace sss
{

struct LocalSurfels;

// A texel's surfel where another piece's surface is nearer the light (x < 0 is "none").
constexpr float kForeignSurfel = -2.0f;

// One directional light's map over all pieces, in this piece's local frame.
struct PieceMap
{
  OrthoView view;
  double w_origin = 0.0;     // the local frame's origin along the map's w, world mm
  double w_reference = 0.0;  // the middle of all pieces' surfels along w, world mm
};

// Fits the map of the light towards `direction` (local frame) over all pieces, at texels of at
// least `texel` mm and at most `max_size` a side. `local` is null for a piece without surfels.
// Collective: one reduction of 8 values.
PieceMap fit_over_pieces(vtkSubsurfacePieces* pieces, const LocalSurfels* local,
  const Eigen::Vector3d& direction, double texel, int max_size);

// Keeps in each texel of `map` the surface nearest the light over all pieces. `depth` and
// `surfel` are this piece's atlas (atlas_width wide; depth as the light-map shader wrote it with
// an orthographic depth range of `reach` mm, surfel two floats a texel), the map at column
// map_x; null for a piece without surfels. Returns how many texels became shadow. Collective:
// one reduction of the map's texels.
long mark_foreign_texels(vtkSubsurfacePieces* pieces, const PieceMap& map, double reach,
  const float* depth, float* surfel, int atlas_width, int map_x);

}

#endif
