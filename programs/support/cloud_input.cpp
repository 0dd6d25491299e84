#include "cloud_input.h"

#include <pcl/point_types.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include "sssPclSurfels.h"

namespace sss::cli {

LoadedCloud load_cloud(const std::string& path, std::size_t mesh_samples, std::size_t memory_cap,
                       double isolation_ratio, bool denoise) {
  LoadOptions load;
  load.mesh_samples = mesh_samples;
  load.memory_cap = memory_cap;
  const auto points = loadPointCloud<pcl::PointXYZRGBNormal>(path, load);
  SurfelOptions options;
  options.drop_isolated = isolation_ratio > 0.0;
  if (options.drop_isolated) options.isolation_ratio = isolation_ratio;
  options.denoise = denoise;
  const Surfels surfels = makeSurfels(points, options);

  vtkPolyData* polydata = surfels.polydata;
  vtkDataArray* normals = polydata->GetPointData()->GetNormals();
  vtkDataArray* colours = surfels.has_colours ? polydata->GetPointData()->GetScalars() : nullptr;
  LoadedCloud loaded;
  SurfelCloud& cloud = loaded.cloud;
  for (vtkIdType i = 0; i < polydata->GetNumberOfPoints(); ++i) {
    double x[3], n[3];
    polydata->GetPoint(i, x);
    normals->GetTuple(i, n);
    cloud.positions.emplace_back(x[0], x[1], x[2]);
    cloud.normals.emplace_back(n[0], n[1], n[2]);
    if (colours) {
      double c[3];
      colours->GetTuple(i, c);
      cloud.albedo.push_back(Rgb{c[0] / 255.0, c[1] / 255.0, c[2] / 255.0});
    }
  }
  cloud.radius = surfels.spacing;
  loaded.isolated = surfels.isolated_points;
  loaded.largest_isolation = surfels.largest_isolation;
  loaded.denoised = surfels.denoised;
  loaded.noise_median = surfels.noise_median;
  loaded.noise_p90 = surfels.noise_p90;
  cloud.validate();
  loaded.description = points.description + "\n" + surfels.summary();
  return loaded;
}

}  // namespace sss::cli
