#include "sssPclMeshSampling.h"

#include <pcl/conversions.h>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <vector>

namespace sss {
namespace {

struct Triangle {
  pcl::index_t a, b, c;
};

// Polygons fanned into triangles, dropping those with a corner that names no vertex.
std::vector<Triangle> triangles_of(const pcl::PolygonMesh& mesh, std::size_t vertex_count) {
  std::vector<Triangle> triangles;
  for (const pcl::Vertices& polygon : mesh.polygons) {
    const auto& v = polygon.vertices;
    for (std::size_t k = 2; k < v.size(); ++k) {
      const Triangle t{v[0], v[k - 1], v[k]};
      const auto [lowest, highest] = std::minmax({t.a, t.b, t.c});
      if (lowest >= 0 && static_cast<std::size_t>(highest) < vertex_count) triangles.push_back(t);
    }
  }
  return triangles;
}

Eigen::Vector3f position(const pcl::PointXYZRGB& p) { return p.getVector3fMap(); }

// Twice the triangle's area times its unit normal (right-handed in the winding).
Eigen::Vector3f area_normal(const pcl::PointCloud<pcl::PointXYZRGB>& v, const Triangle& t) {
  return (position(v[t.b]) - position(v[t.a])).cross(position(v[t.c]) - position(v[t.a]));
}

pcl::PointCloud<pcl::PointXYZRGB> vertices_of(const pcl::PolygonMesh& mesh) {
  pcl::PointCloud<pcl::PointXYZRGB> vertices;
  pcl::fromPCLPointCloud2(mesh.cloud, vertices);
  return vertices;
}

}  // namespace

pcl::PointCloud<pcl::PointXYZRGBNormal> sampleMeshSurface(const pcl::PolygonMesh& mesh,
                                                          std::size_t samples, unsigned seed) {
  const pcl::PointCloud<pcl::PointXYZRGB> vertices = vertices_of(mesh);
  const std::vector<Triangle> triangles = triangles_of(mesh, vertices.size());
  std::vector<double> cumulative_area;
  cumulative_area.reserve(triangles.size());
  double total = 0.0;
  for (const Triangle& t : triangles) {
    const double area = 0.5 * area_normal(vertices, t).norm();
    total += std::isfinite(area) ? area : 0.0;
    cumulative_area.push_back(total);
  }
  if (!(total > 0.0))
    throw std::invalid_argument("the mesh has no triangle of positive area to sample");

  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  pcl::PointCloud<pcl::PointXYZRGBNormal> out;
  out.resize(samples);
  for (std::size_t i = 0; i < samples; ++i) {
    const double pick = uniform(random) * total;
    const std::size_t k = std::min<std::size_t>(
      std::upper_bound(cumulative_area.begin(), cumulative_area.end(), pick) -
        cumulative_area.begin(),
      triangles.size() - 1);
    const Triangle& t = triangles[k];
    // Uniform in the triangle: sqrt of one variate folds the square onto it.
    const double r1 = std::sqrt(uniform(random)), r2 = uniform(random);
    const float wa = static_cast<float>(1.0 - r1), wb = static_cast<float>(r1 * (1.0 - r2)),
                wc = static_cast<float>(r1 * r2);
    const auto &A = vertices[t.a], &B = vertices[t.b], &C = vertices[t.c];
    pcl::PointXYZRGBNormal& p = out[i];
    p.getVector3fMap() = wa * position(A) + wb * position(B) + wc * position(C);
    p.getNormalVector3fMap() = area_normal(vertices, t).normalized();
    p.r = static_cast<std::uint8_t>(std::lround(wa * A.r + wb * B.r + wc * C.r));
    p.g = static_cast<std::uint8_t>(std::lround(wa * A.g + wb * B.g + wc * C.g));
    p.b = static_cast<std::uint8_t>(std::lround(wa * A.b + wb * B.b + wc * C.b));
    p.a = 255;
  }
  return out;
}

pcl::PointCloud<pcl::PointXYZRGBNormal> meshVerticesWithNormals(const pcl::PolygonMesh& mesh) {
  const pcl::PointCloud<pcl::PointXYZRGB> vertices = vertices_of(mesh);
  std::vector<Eigen::Vector3f> summed(vertices.size(), Eigen::Vector3f::Zero());
  for (const Triangle& t : triangles_of(mesh, vertices.size())) {
    const Eigen::Vector3f n = area_normal(vertices, t);
    if (!n.allFinite()) continue;
    summed[t.a] += n;
    summed[t.b] += n;
    summed[t.c] += n;
  }
  pcl::PointCloud<pcl::PointXYZRGBNormal> out;
  out.resize(vertices.size());
  out.width = vertices.width;
  out.height = vertices.height;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    pcl::PointXYZRGBNormal& p = out[i];
    p.getVector3fMap() = position(vertices[i]);
    const float length = summed[i].norm();
    p.getNormalVector3fMap() = length > 0.0f ? Eigen::Vector3f(summed[i] / length)
                                             : Eigen::Vector3f::Zero();
    p.rgba = vertices[i].rgba;
  }
  return out;
}

}  // namespace sss
