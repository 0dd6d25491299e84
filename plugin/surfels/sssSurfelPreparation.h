// Prepared surfels: a vtkPolyData's points and normals as the core's validated SurfelCloud
// (finite points, unit normals, the cells' radius in cloud.radius, and in cloud.radii each
// disc's as the camera and the lights see it: the radius that closes the surface, one for all
// or, where the density varies, one per point: splat_coverage.h), shared by the surfel mapper
// and the pass.
#ifndef sssSurfelPreparation_h
#define sssSurfelPreparation_h

#include "material.h"
#include "splat_coverage.h"
#include "surfel_cloud.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

class vtkFloatArray;
class vtkPolyData;
class vtkUnsignedCharArray;

namespace sss
{

struct PreparedSurfels
{
  SurfelCloud cloud;                          // scene units, validated
  CloudReport report;
  std::array<double, 3> centre{ { 0, 0, 0 } };  // the kept points' Bounds::frame_origin
  std::vector<std::uint8_t> rgba;             // 4 per kept point
  double view_radius = 0.0;                   // the view's uniform radius, or the per-point median
  bool per_point_radii = false;               // cloud.radii differ (else all are view_radius)
  double uncovered = 0.0;                     // measured at view_radius (automatic, uniform)
  double spacing_spread = 1.0;
  std::size_t drawn = 0;                      // the first `drawn` kept points are drawn; the
                                              // rest are ghosts (lit and scattering only)
  std::string error;                          // why nothing can be drawn, or empty
};

// How the radius is found: `radius` > 0 is taken as it is; else choose_splat_radii with
// `mode`, `coverage_target` and `scale`. A point-data array named `radius_array` (1 component,
// scene units) gives each point its own radius in the view.
struct RadiusChoice
{
  double radius = 0.0;
  double scale = 1.0;
  double coverage_target = kDefaultCoverageTarget;
  SplatRadiusMode mode = SplatRadiusMode::Automatic;
  std::string radius_array;
};

// colours (RGBA per input point) may be null: then every point gets `fallback`.
PreparedSurfels prepare_surfels(vtkPolyData* input, const RadiusChoice& choice,
  vtkUnsignedCharArray* colours, const std::array<std::uint8_t, 4>& fallback);

// B given per input point (3 components, input order) in the kept surfels' order; false when
// `given` does not hold 3 components for every input point.
bool radiance_in_surfel_order(
  const PreparedSurfels& surfels, vtkFloatArray* given, std::vector<Rgb>& B);

// B per kept surfel into `B` in input order, 3 components; points not kept are NaN.
void radiance_in_input_order(
  const PreparedSurfels& surfels, const std::vector<Rgb>& values, vtkFloatArray* B);

}

#endif
