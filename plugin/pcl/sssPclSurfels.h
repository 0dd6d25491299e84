// A PCL cloud as surfels for vtkSurfelMapper: finite points that stand on a surface (isolated
// ones left out: core/surfels/isolated_points.h), unit normals (kept, or estimated
// with NormalEstimationOMP over a neighbourhood taken from the spacing found with PCL's
// kd-tree), and colours kept as per-point albedo. The disc radius is the mapper's: the one
// that closes the surface (vtkSurfelMapper::SetCoverageTarget).
#pragma once

#include <pcl/point_cloud.h>
#include <vtkSmartPointer.h>

#include <Eigen/Core>
#include <cstddef>
#include <string>

#include "sssPclLoading.h"

class vtkPolyData;

namespace sss {

enum class NormalOrientation {
  Automatic,         // towards the sensor for organised clouds or a set sensor origin, else Outward
  Outward,           // away from the cloud's centroid (closed objects)
  TowardsViewpoint,  // towards SurfelOptions::viewpoint (scans from one place, terrain)
};

struct SurfelOptions {
  NormalOrientation orientation = NormalOrientation::Automatic;
  Eigen::Vector3f viewpoint = Eigen::Vector3f::Zero();
  // Normal estimation neighbourhood radius in scene units; 0: NormalRadiusSpacings times the
  // mean spacing. Points with too few neighbours in it fall back to their NormalNeighbours
  // nearest.
  double normal_radius = 0.0;
  double normal_radius_spacings = 3.0;
  int normal_neighbours = 16;
  // Points whose mean distance to their isolation_neighbours nearest exceeds isolation_ratio
  // times the median of that mean among those neighbours are left out (stray returns, flying
  // pixels): their discs would be huge and would shade and light real surface.
  bool drop_isolated = true;
  int isolation_neighbours = 16;
  double isolation_ratio = 5.0;
  // Points moved onto the smooth surface fitted around each over a neighbourhood sized from the
  // depth noise measured there, the normals (when estimated) that surface's, so that a scan
  // shows its surface and not its noise (core/surfels/denoised_surface.h); normal_tolerance is the
  // normal's standard error in radians the neighbourhood is sized for. Off: the points as
  // given, normals by NormalEstimationOMP over normal_radius.
  bool denoise = true;
  double normal_tolerance = 0.02;
};

struct Surfels {
  // Double-precision points (georeferenced coordinates keep their digits), "Normals"
  // (float, unit), when the cloud has colours "Colors" (unsigned char RGB) as scalars, and
  // when denoised "Noise" (float, scene units: the depth noise measured around each point).
  vtkSmartPointer<vtkPolyData> polydata;
  double spacing = 0.0;  // mean distance to the nearest other point, scene units
  bool has_colours = false;
  bool estimated_normals = false;
  std::size_t input_points = 0;
  std::size_t nonfinite_points = 0;      // NaN or infinite position (organised clouds' holes)
  std::size_t points_without_normal = 0;  // no usable normal given or estimated
  std::size_t isolated_points = 0;        // left out as isolated (SurfelOptions::drop_isolated)
  double largest_isolation = 0.0;         // the largest isolation ratio among the finite points
  bool denoised = false;                  // the points are on the measured surface
  double noise_median = 0.0, noise_p90 = 0.0;  // depth noise measured around the points
  std::string denoise_summary;            // DenoiseReport::summary()
  std::size_t size() const;
  std::string summary() const;
};

// Throws InputError naming what is wrong (std::invalid_argument for bad isolation settings):
// no finite point, too few points for normals, all
// points at one place. Normals are kept when the point type has them and any of them is
// finite and non-zero; otherwise estimated. Instantiated for PointXYZ, PointNormal,
// PointXYZRGB, PointXYZRGBNormal and PointSurfel.
template <typename PointT>
Surfels makeSurfels(const pcl::PointCloud<PointT>& cloud, const SurfelOptions& options = {});

// As above, with what the file said about normals and colours.
template <typename PointT>
Surfels makeSurfels(const LoadedPointCloud<PointT>& loaded, const SurfelOptions& options = {});

}  // namespace sss
