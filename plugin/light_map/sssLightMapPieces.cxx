#include "sssLightMapPieces.h"

#include "vtkSubsurfacePieces.h"

#include "local_surfels.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sss
{

PieceMap fit_over_pieces(vtkSubsurfacePieces* pieces, const LocalSurfels* local,
  const Eigen::Vector3d& direction, double texel, int max_size)
{
  const double inf = std::numeric_limits<double>::infinity();
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();  // as core's fit_light_view
  // The map's axes, from any two points: they depend on the light alone.
  const OrthoView axes =
    OrthoView::fit_pixel({ Eigen::Vector3d::Zero() }, 1.0, direction, up, 1.0, 1);
  const Eigen::Vector3d origin_mm =
    local ? Eigen::Vector3d(local->frame.origin * local->frame.mm_per_unit)
          : Eigen::Vector3d::Zero();
  const Eigen::Vector3d offset(
    origin_mm.dot(axes.u), origin_mm.dot(axes.v), origin_mm.dot(axes.w));
  // Minima of: texel, -largest disc radius, the lowest and (negated) highest u, v, w.
  double reduced[8] = { inf, inf, inf, inf, inf, inf, inf, inf };
  if (local && local->size() > 0)
  {
    reduced[0] = texel;
    reduced[1] = -local->max_disc_radius();
    for (const Eigen::Vector3d& p : local->positions)
    {
      const Eigen::Vector3d q(p.dot(axes.u), p.dot(axes.v), p.dot(axes.w));
      for (int a = 0; a < 3; ++a)
      {
        reduced[2 + a] = std::min(reduced[2 + a], q[a] + offset[a]);
        reduced[5 + a] = std::min(reduced[5 + a], -(q[a] + offset[a]));
      }
    }
  }
  pieces->MinimumOverPieces(reduced, 8);
  PieceMap map;
  if (!std::isfinite(reduced[0]))  // no piece has surfels
  {
    map.view = OrthoView::fit_pixel({}, 0.0, direction, up, 1.0, 1);
    return map;
  }
  // Two points spanning every piece's surfels along u and v, in this piece's frame.
  const Eigen::Vector3d lo = (reduced[2] - offset[0]) * axes.u + (reduced[3] - offset[1]) * axes.v;
  const Eigen::Vector3d hi = (-reduced[5] - offset[0]) * axes.u + (-reduced[6] - offset[1]) * axes.v;
  map.view = OrthoView::fit_pixel({ lo, hi }, -reduced[1], direction, up, reduced[0], max_size);
  map.w_origin = offset[2];
  map.w_reference = 0.5 * (reduced[4] - reduced[7]);
  return map;
}

long mark_foreign_texels(vtkSubsurfacePieces* pieces, const PieceMap& map, double reach,
  const float* depth, float* surfel, int atlas_width, int map_x)
{
  const int w = map.view.width, h = map.view.height;
  const auto texels = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  // Each texel's distance below the reference along the light (mm; smaller is nearer the
  // light), +inf where this piece has no surface: the light-map shader's depth is
  // (1 - z / reach) / 2 with z along w in the local frame.
  std::vector<float> mine(texels, std::numeric_limits<float>::infinity());
  if (depth)
  {
    for (int j = 0; j < h; ++j)
    {
      for (int i = 0; i < w; ++i)
      {
        const std::size_t at = static_cast<std::size_t>(j) * atlas_width + map_x + i;
        if (surfel[2 * at] >= 0.0f)
        {
          const double z = reach * (1.0 - 2.0 * depth[at]) + map.w_origin;
          mine[static_cast<std::size_t>(j) * w + i] = static_cast<float>(map.w_reference - z);
        }
      }
    }
  }
  std::vector<float> nearest = mine;
  pieces->MinimumOverPieces(nearest.data(), static_cast<vtkIdType>(texels));
  if (!depth)
  {
    return 0;
  }
  // The same surfel seen by two pieces (a ghost here, owned there) differs by rounding alone;
  // another piece's own surface is at least the kernel's reach away (else it is a ghost here).
  const float tolerance = static_cast<float>(1e-3 * map.view.pixel + 1e-6 * reach);
  long foreign = 0;
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      const std::size_t k = static_cast<std::size_t>(j) * w + i;
      if (nearest[k] < mine[k] - tolerance)
      {
        const std::size_t at = static_cast<std::size_t>(j) * atlas_width + map_x + i;
        surfel[2 * at] = kForeignSurfel;
        surfel[2 * at + 1] = kForeignSurfel;
        ++foreign;
      }
    }
  }
  return foreign;
}

}
