// Prepared surfels: a vtkPolyData's points and normals as the core's validated SurfelCloud
// (finite points, unit normals, one radius), shared by the surfel mapper and the pass.
#ifndef sssSurfelPreparation_h
#define sssSurfelPreparation_h

#include "surfel_cloud.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

class vtkPolyData;
class vtkUnsignedCharArray;

namespace sss
{

struct PreparedSurfels
{
  SurfelCloud cloud;                          // scene units, validated
  CloudReport report;
  std::array<double, 3> centre{ { 0, 0, 0 } };  // bounds centre of the kept points
  std::vector<std::uint8_t> rgba;             // 4 per kept point
  std::string error;                          // why nothing can be drawn, or empty
};

// radius <= 0 picks the mean nearest-neighbour spacing. colours (RGBA per input point) may be
// null: then every point gets `fallback`.
PreparedSurfels prepare_surfels(vtkPolyData* input, double radius, double spacing_scale,
  vtkUnsignedCharArray* colours,
  const std::array<std::uint8_t, 4>& fallback);

}

#endif
