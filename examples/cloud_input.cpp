#include "cloud_input.h"

#include <pcl/PCLPointCloud2.h>
#include <pcl/common/centroid.h>
#include <pcl/conversions.h>
#include <pcl/features/normal_3d_omp.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>
#include <pcl/search/kdtree.h>

#include <fstream>
#include <stdexcept>

#include "scan_io.h"

namespace sss::cli {
namespace {

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

bool has_field(const pcl::PCLPointCloud2& blob, const std::string& name) {
  for (const auto& f : blob.fields)
    if (f.name == name) return true;
  return false;
}

constexpr int kNormalNeighbours = 16;

SurfelCloud load_pcd(const std::string& path) {
  pcl::PCLPointCloud2 blob;
  if (pcl::io::loadPCDFile(path, blob) < 0)
    throw std::runtime_error(path + ": not a readable PCD file");
  SurfelCloud cloud;
  if (has_field(blob, "normal_x")) {
    pcl::PointCloud<pcl::PointNormal> points;
    pcl::fromPCLPointCloud2(blob, points);
    for (const auto& p : points) {
      cloud.positions.emplace_back(p.x, p.y, p.z);
      cloud.normals.emplace_back(p.normal_x, p.normal_y, p.normal_z);
    }
    return cloud;
  }
  pcl::PointCloud<pcl::PointXYZ>::Ptr points(new pcl::PointCloud<pcl::PointXYZ>);
  pcl::fromPCLPointCloud2(blob, *points);
  pcl::PointCloud<pcl::PointXYZ>::Ptr finite(new pcl::PointCloud<pcl::PointXYZ>);
  for (const auto& p : *points)
    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) finite->push_back(p);
  if (finite->size() < static_cast<std::size_t>(kNormalNeighbours))
    throw std::runtime_error(path + ": " + std::to_string(finite->size()) +
                             " finite points, too few to estimate normals (needs " +
                             std::to_string(kNormalNeighbours) + ")");
  // Normals from the 16 nearest neighbours, oriented away from the centroid (the renderer
  // lights whichever side faces the light, so orientation only needs to be consistent).
  pcl::NormalEstimationOMP<pcl::PointXYZ, pcl::Normal> estimate;
  estimate.setInputCloud(finite);
  estimate.setSearchMethod(pcl::search::KdTree<pcl::PointXYZ>::Ptr(new pcl::search::KdTree<pcl::PointXYZ>));
  estimate.setKSearch(kNormalNeighbours);
  pcl::PointCloud<pcl::Normal> normals;
  estimate.compute(normals);
  Eigen::Vector4d centroid;
  pcl::compute3DCentroid(*finite, centroid);
  for (std::size_t i = 0; i < finite->size(); ++i) {
    const auto& p = (*finite)[i];
    Eigen::Vector3d n(normals[i].normal_x, normals[i].normal_y, normals[i].normal_z);
    const Eigen::Vector3d x(p.x, p.y, p.z);
    if ((x - centroid.head<3>()).dot(n) < 0) n = -n;
    cloud.positions.push_back(x);
    cloud.normals.push_back(n);
  }
  return cloud;
}

}  // namespace

LoadedCloud load_cloud(const std::string& path) {
  if (!std::ifstream(path).good()) throw std::runtime_error(path + ": cannot be opened");
  LoadedCloud loaded;
  if (ends_with(path, ".ply") || ends_with(path, ".ply.gz")) {
    try {
      loaded.cloud = sss::test::load_ply_mesh(path);
    } catch (const std::exception& e) {
      throw std::runtime_error(path + ": " + e.what());
    }
  } else if (ends_with(path, ".pcd")) {
    loaded.cloud = load_pcd(path);
    loaded.cloud.radius = 1.0;  // replaced by the spacing below
  } else {
    throw std::runtime_error(path + ": unknown extension (use .pcd, .ply or .ply.gz)");
  }
  if (loaded.cloud.positions.empty()) throw std::runtime_error(path + ": the file has no points");
  const bool from_spacing = ends_with(path, ".pcd");
  const CloudReport report = loaded.cloud.validate();
  if (loaded.cloud.empty())
    throw std::runtime_error(path + ": no point has a finite position and normal");
  if (from_spacing) loaded.cloud.radius = loaded.cloud.mean_spacing();
  if (!(loaded.cloud.radius > 0.0))
    throw std::runtime_error(path + ": all points coincide; there is no surface to render");
  loaded.description = path + ": " + report.summary();
  return loaded;
}

}  // namespace sss::cli
