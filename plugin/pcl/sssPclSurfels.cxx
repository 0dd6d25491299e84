#include "sssPclSurfels.h"

#include <pcl/common/centroid.h>
#include <pcl/features/normal_3d_omp.h>
#include <pcl/point_types.h>
#include <pcl/search/kdtree.h>

#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

#include <cmath>
#include <vector>

#include "denoised_surface.h"
#include "isolated_points.h"
#include "surfel_index.h"

namespace sss {
namespace {

using XyzCloud = pcl::PointCloud<pcl::PointXYZ>;

// Normals by NormalEstimationOMP over a radius; points with fewer than three neighbours in it
// get theirs from their k nearest. Unusable normals stay NaN.
pcl::PointCloud<pcl::Normal> estimate_normals(const XyzCloud::ConstPtr& xyz,
                                              const pcl::search::KdTree<pcl::PointXYZ>::Ptr& tree,
                                              double radius, int neighbours) {
  pcl::NormalEstimationOMP<pcl::PointXYZ, pcl::Normal> estimation;
  estimation.setInputCloud(xyz);
  estimation.setSearchMethod(tree);
  estimation.setRadiusSearch(radius);
  pcl::PointCloud<pcl::Normal> normals;
  estimation.compute(normals);

  pcl::IndicesPtr failed(new pcl::Indices);
  for (std::size_t i = 0; i < normals.size(); ++i)
    if (!std::isfinite(normals[i].normal_x)) failed->push_back(static_cast<pcl::index_t>(i));
  if (failed->empty()) return normals;
  pcl::NormalEstimationOMP<pcl::PointXYZ, pcl::Normal> fallback;
  fallback.setInputCloud(xyz);
  fallback.setIndices(failed);
  fallback.setSearchMethod(tree);
  fallback.setKSearch(neighbours);
  pcl::PointCloud<pcl::Normal> refilled;
  fallback.compute(refilled);
  for (std::size_t k = 0; k < failed->size(); ++k) normals[(*failed)[k]] = refilled[k];
  return normals;
}

template <typename PointT>
Eigen::Vector3f given_normal(const PointT& p) {
  if constexpr (pcl::traits::has_normal_v<PointT>)
    return Eigen::Vector3f(p.normal_x, p.normal_y, p.normal_z);
  else
    return Eigen::Vector3f::Zero();
}

bool usable(const Eigen::Vector3f& n) { return n.allFinite() && n.squaredNorm() > 1e-24f; }

template <typename PointT>
Surfels build(const pcl::PointCloud<PointT>& cloud, bool normals_given, bool colours_given,
              const SurfelOptions& options) {
  Surfels s;
  s.input_points = cloud.size();
  XyzCloud::Ptr xyz(new XyzCloud);
  std::vector<std::size_t> source;  // input index of each finite point
  std::vector<Eigen::Vector3d> finite;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const PointT& p = cloud[i];
    if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))) continue;
    finite.emplace_back(p.x, p.y, p.z);
    source.push_back(i);
  }
  s.nonfinite_points = cloud.size() - finite.size();
  if (finite.empty())
    throw InputError("no point has a finite position (" + std::to_string(cloud.size()) +
                     " points, all NaN or infinite)");
  IsolationSettings isolation;
  isolation.enabled = options.drop_isolated;
  isolation.neighbours = options.isolation_neighbours;
  isolation.ratio = options.isolation_ratio;
  IsolationReport isolated;
  const std::vector<bool> on_surface = find_surface_points(finite, isolation, &isolated);
  s.isolated_points = isolated.isolated;
  s.largest_isolation = isolated.largest_ratio;
  std::vector<Eigen::Vector3d> measured;
  measured.reserve(finite.size() - isolated.isolated);
  std::size_t kept_finite = 0;
  for (std::size_t k = 0; k < finite.size(); ++k) {
    if (!on_surface[k]) continue;
    measured.push_back(finite[k]);
    source[kept_finite++] = source[k];
  }
  source.resize(kept_finite);
  // The surface the scan measured (core/surfels/denoised_surface.h): points on it, its normals.
  DenoiseSettings denoising;
  denoising.enabled = options.denoise;
  denoising.normal_tolerance = options.normal_tolerance;
  DenoiseReport denoised_report;
  const DenoisedSurface surface = denoise_surface(measured, denoising, &denoised_report);
  s.denoised = denoising.enabled && denoised_report.points > 0;
  s.noise_median = denoised_report.median_noise;
  s.noise_p90 = denoised_report.p90_noise;
  s.denoise_summary = s.denoised ? denoised_report.summary() : std::string();
  xyz->reserve(surface.positions.size());
  for (const Eigen::Vector3d& p : surface.positions)
    xyz->push_back(pcl::PointXYZ(static_cast<float>(p.x()), static_cast<float>(p.y()),
                                 static_cast<float>(p.z())));

  pcl::search::KdTree<pcl::PointXYZ>::Ptr tree(new pcl::search::KdTree<pcl::PointXYZ>);
  tree->setInputCloud(xyz);
  s.spacing = mean_spacing(surface.positions,
                           [&](std::size_t i, int k, std::vector<std::size_t>& out) {
                             pcl::Indices indices;
                             std::vector<float> squared;
                             tree->nearestKSearch((*xyz)[i], k, indices, squared);
                             out.assign(indices.begin(), indices.end());
                           });
  if (!(s.spacing > 0.0))
    throw InputError("all " + std::to_string(xyz->size()) +
                     " finite points lie at one place; there is no surface");

  std::vector<Eigen::Vector3f> normals(xyz->size());
  bool any_given = false;
  if (normals_given)
    for (std::size_t k = 0; k < xyz->size(); ++k) {
      normals[k] = given_normal(cloud[source[k]]);
      any_given = any_given || usable(normals[k]);
    }
  s.estimated_normals = !any_given;
  if (s.estimated_normals) {
    if (xyz->size() < 3)
      throw InputError(std::to_string(xyz->size()) +
                       " finite points, too few to estimate normals (needs at least 3)");
    const double radius = options.normal_radius > 0.0
                            ? options.normal_radius
                            : options.normal_radius_spacings * s.spacing;
    pcl::PointCloud<pcl::Normal> estimated;
    if (s.denoised) {
      estimated.resize(xyz->size());
      for (std::size_t k = 0; k < xyz->size(); ++k)
        estimated[k].getNormalVector3fMap() = surface.normals[k].cast<float>();
    } else {
      estimated = estimate_normals(xyz, tree, radius, options.normal_neighbours);
    }
    NormalOrientation orientation = options.orientation;
    Eigen::Vector3f viewpoint = options.viewpoint;
    if (orientation == NormalOrientation::Automatic) {
      const bool sensor = cloud.isOrganized() || !cloud.sensor_origin_.template head<3>().isZero();
      orientation = sensor ? NormalOrientation::TowardsViewpoint : NormalOrientation::Outward;
      viewpoint = cloud.sensor_origin_.template head<3>();
    }
    Eigen::Vector4f centroid;
    pcl::compute3DCentroid(*xyz, centroid);
    for (std::size_t k = 0; k < xyz->size(); ++k) {
      Eigen::Vector3f n = estimated[k].getNormalVector3fMap();
      const Eigen::Vector3f x = (*xyz)[k].getVector3fMap();
      const Eigen::Vector3f away = orientation == NormalOrientation::Outward
                                     ? Eigen::Vector3f(x - centroid.head<3>())
                                     : Eigen::Vector3f(viewpoint - x);
      if (n.dot(away) < 0.0f) n = -n;
      normals[k] = n;
    }
  }

  std::vector<std::size_t> kept;
  for (std::size_t k = 0; k < xyz->size(); ++k)
    if (usable(normals[k])) kept.push_back(k);
  s.points_without_normal = xyz->size() - kept.size();
  if (kept.empty())
    throw InputError(std::to_string(xyz->size()) +
                     " finite points, but too few neighbours around any of them for a normal");

  s.has_colours = colours_given && pcl::traits::has_color_v<PointT>;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(kept.size()));
  vtkNew<vtkFloatArray> normal_array;
  normal_array->SetName("Normals");
  normal_array->SetNumberOfComponents(3);
  normal_array->SetNumberOfTuples(static_cast<vtkIdType>(kept.size()));
  vtkNew<vtkFloatArray> noise_array;  // the depth noise measured around each point
  noise_array->SetName("Noise");
  if (s.denoised) noise_array->SetNumberOfTuples(static_cast<vtkIdType>(kept.size()));
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetName("Colors");
  colours->SetNumberOfComponents(3);
  if (s.has_colours) colours->SetNumberOfTuples(static_cast<vtkIdType>(kept.size()));
  for (std::size_t j = 0; j < kept.size(); ++j) {
    const std::size_t k = kept[j];
    const PointT& p = cloud[source[k]];
    const vtkIdType id = static_cast<vtkIdType>(j);
    points->SetPoint(id, surface.positions[k].data());
    const Eigen::Vector3f n = normals[k].normalized();
    normal_array->SetTuple3(id, n.x(), n.y(), n.z());
    if (s.denoised) noise_array->SetValue(id, surface.noise[k]);
    if constexpr (pcl::traits::has_color_v<PointT>)
      if (s.has_colours) colours->SetTuple3(id, p.r, p.g, p.b);
  }
  s.polydata = vtkSmartPointer<vtkPolyData>::New();
  s.polydata->SetPoints(points);
  s.polydata->GetPointData()->SetNormals(normal_array);
  if (s.has_colours) s.polydata->GetPointData()->SetScalars(colours);
  if (s.denoised) s.polydata->GetPointData()->AddArray(noise_array);
  return s;
}

}  // namespace

std::size_t Surfels::size() const {
  return polydata ? static_cast<std::size_t>(polydata->GetNumberOfPoints()) : 0;
}

std::string Surfels::summary() const {
  std::string text = std::to_string(size()) + " surfels of " + std::to_string(input_points) +
                     " points, mean spacing " + std::to_string(spacing);
  text += estimated_normals ? ", normals estimated" : ", normals given";
  if (has_colours) text += ", colours as albedo";
  if (nonfinite_points) text += ", " + std::to_string(nonfinite_points) + " non-finite dropped";
  if (isolated_points) text += ", " + std::to_string(isolated_points) + " isolated dropped";
  if (denoised) text += ", on the measured surface (" + denoise_summary + ")";
  if (points_without_normal)
    text += ", " + std::to_string(points_without_normal) + " without a normal dropped";
  return text;
}

template <typename PointT>
Surfels makeSurfels(const pcl::PointCloud<PointT>& cloud, const SurfelOptions& options) {
  return build(cloud, pcl::traits::has_normal_v<PointT>, pcl::traits::has_color_v<PointT>,
               options);
}

template <typename PointT>
Surfels makeSurfels(const LoadedPointCloud<PointT>& loaded, const SurfelOptions& options) {
  try {
    return build(*loaded.cloud, loaded.has_normals, loaded.has_colours, options);
  } catch (const InputError& e) {
    throw InputError(loaded.path + ": " + e.what());
  }
}

#define SSS_INSTANTIATE_SURFELS(PointT)                                                      \
  template Surfels makeSurfels<PointT>(const pcl::PointCloud<PointT>&, const SurfelOptions&); \
  template Surfels makeSurfels<PointT>(const LoadedPointCloud<PointT>&, const SurfelOptions&);
SSS_INSTANTIATE_SURFELS(pcl::PointXYZ)
SSS_INSTANTIATE_SURFELS(pcl::PointNormal)
SSS_INSTANTIATE_SURFELS(pcl::PointXYZRGB)
SSS_INSTANTIATE_SURFELS(pcl::PointXYZRGBNormal)
SSS_INSTANTIATE_SURFELS(pcl::PointSurfel)
#undef SSS_INSTANTIATE_SURFELS

}  // namespace sss
