// Uniform sampling of a triangle mesh's surface, the way pcl_mesh_sampling does it: triangles
// chosen with probability proportional to their area, a uniform point inside each.
#pragma once

#include <pcl/PolygonMesh.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstddef>

namespace sss {

// N samples with the triangle's normal (from its winding) and, when the mesh has colours, the
// barycentric blend of its corners' colours. Polygons with more than three corners are fanned.
// Throws std::invalid_argument for a mesh without triangles of positive area.
pcl::PointCloud<pcl::PointXYZRGBNormal> sampleMeshSurface(const pcl::PolygonMesh& mesh,
                                                          std::size_t samples, unsigned seed);

// Area-weighted vertex normals from the faces' winding (zero for a vertex on no face).
pcl::PointCloud<pcl::PointXYZRGBNormal> meshVerticesWithNormals(const pcl::PolygonMesh& mesh);

}  // namespace sss
